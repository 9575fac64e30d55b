package ifold.check;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Groups found by vectors of numbers that agree within a tolerance: a plane by its normal and
 * offset, a line by its direction and a point. Each group is filed under its vector rounded to
 * a quantum per coordinate; a vector is looked up in its own cell and, for each coordinate
 * within a quarter quantum of a cell's border, in the cell beyond too, so that a tolerance below
 * a quarter quantum finds every group that agrees.
 */
final class NearKeys {
    private final double[] quanta;
    private final Map<Long, List<Integer>> cells = new HashMap<>();
    private final List<double[]> keys = new ArrayList<>();

    NearKeys(double... quanta) {
        this.quanta = quanta;
    }

    double[] key(int group) {
        return keys.get(group);
    }

    /**
     * The group whose key agrees with {@code values} within {@code tolerances}, coordinate by
     * coordinate, or -1.
     */
    int find(double[] values, double[] tolerances) {
        int dims = values.length;
        long[] base = new long[dims];
        int[] step = new int[dims];
        for (int i = 0; i < dims; i++) {
            double r = values[i] / quanta[i];
            base[i] = Math.round(r);
            double frac = r - base[i];
            step[i] = frac > 0.25 ? 1 : frac < -0.25 ? -1 : 0;
        }
        long[] cell = new long[dims];
        for (int mask = 0; mask < 1 << dims; mask++) {
            boolean used = true;
            for (int i = 0; i < dims; i++) {
                boolean moved = (mask >> i & 1) == 1;
                if (moved && step[i] == 0) {
                    used = false;
                    break;
                }
                cell[i] = base[i] + (moved ? step[i] : 0);
            }
            if (!used) {
                continue;
            }
            for (int group : cells.getOrDefault(hash(cell), List.of())) {
                double[] key = keys.get(group);
                boolean agrees = true;
                for (int i = 0; i < dims && agrees; i++) {
                    agrees = Math.abs(key[i] - values[i]) <= tolerances[i];
                }
                if (agrees) {
                    return group;
                }
            }
        }
        return -1;
    }

    /** Files a new group under {@code values}; returns its number. */
    int add(double[] values) {
        long[] cell = new long[values.length];
        for (int i = 0; i < values.length; i++) {
            cell[i] = Math.round(values[i] / quanta[i]);
        }
        int group = keys.size();
        keys.add(values.clone());
        cells.computeIfAbsent(hash(cell), k -> new ArrayList<>(1)).add(group);
        return group;
    }

    private static long hash(long[] cell) {
        long h = 0x9E3779B97F4A7C15L;
        for (long c : cell) {
            h = (h ^ c) * 0xBF58476D1CE4E5B9L;
            h ^= h >>> 31;
        }
        return h;
    }
}
