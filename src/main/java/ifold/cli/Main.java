package ifold.cli;

import java.io.PrintWriter;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code ifold} command: the entry point and the only place that calls System.exit. */
@Command(name = "ifold", mixinStandardHelpOptions = true, version = "ifold 0.1.0",
        description = "Wraps polyhedra in a strip of paper, the zig-zag way.",
        subcommands = {AppCommand.class, WrapCommand.class, ViewCommand.class, FoldCommand.class, DemoCommand.class, RefineCommand.class, InfoCommand.class, GenerateCommand.class, CommandLine.HelpCommand.class})
public final class Main implements Runnable {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /** {@code ifold} alone: the window where there is a display; without one, the usage error of old. */
    @Override
    public void run() {
        if (!PaperOutputs.hasDisplay() || !ifold.ui.App.canOpen()) {
            throw new CommandLine.ParameterException(spec.commandLine(), "missing command: try 'ifold --help'");
        }
        try {
            AppCommand.open(null, null);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Under the launcher's own virtual display, the launcher waits for iFold and stops it on
     * Ctrl-C or SIGTERM; killed outright (SIGKILL), it cannot. iFold then notices that its parent
     * is gone and stops too, its shutdown hooks taking back unfinished outputs; the display ends
     * with its last client.
     */
    private static void watchLauncher() {
        if (System.getenv("IFOLD_IN_XVFB") == null) {
            return;
        }
        ProcessHandle parent = ProcessHandle.current().parent().orElse(null);
        if (parent == null) {
            return;
        }
        Thread watch = new Thread(() -> {
            while (parent.isAlive()) {
                try {
                    Thread.sleep(250);
                } catch (InterruptedException e) {
                    return;
                }
            }
            System.err.println("ifold: the launcher was killed: stopping");
            System.exit(143);
        }, "launcher watch");
        watch.setDaemon(true);
        watch.start();
    }

    /** A command line with iFold's error handling: one line per error, never a stack trace. */
    public static CommandLine commandLine(PrintWriter out, PrintWriter err) {
        CommandLine commandLine = new CommandLine(new Main());
        commandLine.setOut(out);
        commandLine.setErr(err);
        commandLine.setParameterExceptionHandler((ex, args) -> {
            CommandLine cmd = ex.getCommandLine();
            cmd.getErr().println("ifold: " + ex.getMessage());
            cmd.getErr().println("Try '" + cmd.getCommandSpec().qualifiedName() + " --help' for more.");
            cmd.getErr().flush();
            return cmd.getCommandSpec().exitCodeOnInvalidInput();
        });
        commandLine.setExecutionExceptionHandler((ex, cmd, parseResult) -> {
            if (ex instanceof UserError error) {
                cmd.getErr().println("ifold: " + ex.getMessage());
                cmd.getErr().flush();
                return error.exitCode();
            }
            // A bug, not bad input: still one line, with the kind of failure so it can be reported.
            cmd.getErr().println("ifold: internal error: " + ex + " (please report it)");
            cmd.getErr().flush();
            return 70;
        });
        return commandLine;
    }

    public static void main(String[] args) {
        watchLauncher();
        PrintWriter out = new PrintWriter(System.out, true);
        PrintWriter err = new PrintWriter(System.err, true);
        int code;
        try {
            code = commandLine(out, err).execute(args);
        } catch (OutOfMemoryError e) {
            // picocli passes Errors through; a model too big for the heap is still the user's to fix.
            err.println("ifold: out of memory: give the JVM more, e.g. JAVA_OPTS=-Xmx8g");
            code = UserError.EXIT_CODE;
        }
        out.flush();
        System.exit(code);
    }
}
