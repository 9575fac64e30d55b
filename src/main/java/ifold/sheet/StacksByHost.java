package ifold.sheet;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.IntFunction;

/**
 * The sheet's stacks, indexed by host: a fold asks for a host's stack at every tuck, landing and
 * test, and a map keyed by boxed host numbers made an Integer for each (hosts past 127) and a
 * hash lookup where an array index does.
 */
final class StacksByHost {
    private Stack[] byHost = new Stack[16];
    private final List<Stack> made = new ArrayList<>();

    /** The stack on {@code host}, or null where no paper has rested there. */
    Stack get(int host) {
        return host < byHost.length ? byHost[host] : null;
    }

    /** The stack on {@code host}, made by {@code make} where there is none yet. */
    Stack computeIfAbsent(int host, IntFunction<Stack> make) {
        Stack stack = get(host);
        if (stack == null) {
            if (host >= byHost.length) {
                byHost = Arrays.copyOf(byHost, Math.max(host + 1, 2 * byHost.length));
            }
            stack = make.apply(host);
            byHost[host] = stack;
            made.add(stack);
        }
        return stack;
    }

    /** Every stack, in the order they were made. */
    List<Stack> values() {
        return made;
    }
}
