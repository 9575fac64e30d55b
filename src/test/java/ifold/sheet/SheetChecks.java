package ifold.sheet;

/** Checks of a folded sheet that every test of a fold can share. */
public final class SheetChecks {
    private SheetChecks() {
    }

    /**
     * No two faces that overlap on a host share a level there: paper never passes through
     * paper. Quadratic in the faces of a host: for tests.
     */
    public static void assertLayersApart(Sheet sheet, int hosts) {
        int[] levels = sheet.levels();
        for (int h = 0; h < hosts; h++) {
            int[] faces = sheet.facesOn(h);
            for (int i = 0; i < faces.length; i++) {
                double[] a = sheet.placed(faces[i]);
                for (int j = i + 1; j < faces.length; j++) {
                    double[] b = sheet.placed(faces[j]);
                    if (levels[faces[i]] == levels[faces[j]] && Polygons2.overlap(a, a.length / 2, b, b.length / 2, sheet.tolerance())) {
                        throw new AssertionError("faces " + faces[i] + " and " + faces[j] + " overlap at level " + levels[faces[i]]
                                + " on host " + h);
                    }
                }
            }
        }
    }
}
