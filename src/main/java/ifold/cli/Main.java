package ifold.cli;

import ifold.io.AtomicFile;
import java.io.PrintWriter;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code ifold} command: the entry point and the only place that calls System.exit. */
@Command(name = "ifold", mixinStandardHelpOptions = true, version = "ifold 0.1.0",
        description = "Wraps polyhedra in a strip of paper, the zig-zag way.")
public final class Main implements Runnable {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /** {@code ifold} alone: the window where there is a display; without one, a usage error saying how to open it and list the commands. */
    @Override
    public void run() {
        if (!PaperOutputs.hasDisplay() || !ifold.ui.App.canOpen()) {
            // What was typed is not wrong where there is a display: say what it would have done, and how to go on.
            throw UserError.usage("missing command: 'ifold' alone opens the window, and there is no display here"
                    + " (where there is one: 'ifold', or 'ifold app FILE'); 'ifold --help' lists the commands");
        }
        try {
            AppCommand.open(null, null, spec.commandLine().getErr());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Gives {@code command}'s subcommands, and theirs, {@code version}. */
    private static void versionEverywhere(CommandLine command, String[] version) {
        for (CommandLine sub : command.getSubcommands().values()) {
            sub.getCommandSpec().version(version);
            versionEverywhere(sub, version);
        }
    }

    /** Set once main has its exit code: a shutdown before that is a signal's (Ctrl-C, SIGTERM, SIGHUP). */
    private static volatile boolean ended;

    /** The status a signal stops the JVM with (128 + its number), once one has; else 0. */
    private static volatile int stopStatus;

    /** How long the shutdown hooks of a signalled run may take before the process halts anyway. */
    private static final long HANG_MILLIS = 5_000;

    /**
     * Ctrl-C, SIGTERM or SIGHUP stop the JVM with 130, 143 or 129 and run the shutdown hooks,
     * which take back every unfinished file ({@link AtomicFile}): one line then says what was
     * left. The launcher execs the JVM, so that the signal reaches it as sent.
     */
    private static void sayWhenInterrupted(PrintWriter err) {
        // A signal stops the JVM while the command's thread runs on: what then fails under it
        // (a renderer whose display its own shutdown hook closed) is the signal's doing, and says
        // nothing; one line says what was left. Failures outside a shutdown are reported as ever.
        Thread.setDefaultUncaughtExceptionHandler((thread, failure) -> {
            if (shuttingDown()) {
                return;
            }
            System.err.print("Exception in thread \"" + thread.getName() + "\" ");
            failure.printStackTrace();
        });
        // The signals handled as the JVM would (exit with 128 + the signal's number, running the
        // shutdown hooks), but with their number known: where a hook hangs (JOGL's, when the signal
        // comes while OpenGL starts up, waits for ever on its own shared-resource thread), the
        // process still ends, with that status, a few seconds on.
        for (String name : new String[] {"INT", "TERM", "HUP"}) {
            try {
                sun.misc.Signal.handle(new sun.misc.Signal(name), signal -> {
                    stopStatus = 128 + signal.getNumber();
                    System.exit(stopStatus);
                });
            } catch (IllegalArgumentException e) {
                // Ignored where the process was started (nohup's SIGHUP): the JVM leaves it so too.
            }
        }
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            if (!ended) {
                Thread halt = new Thread(() -> {
                    try {
                        Thread.sleep(HANG_MILLIS);
                    } catch (InterruptedException e) {
                        return;
                    }
                    Runtime.getRuntime().halt(stopStatus > 0 ? stopStatus : 1);
                }, "halt a hung shutdown");
                halt.setDaemon(true);
                halt.start();
                List<java.nio.file.Path> kept = AtomicFile.written();
                // Whole frames of a sequence stay (each was renamed into place whole): say how many, not each.
                err.println("ifold: interrupted: " + (kept.isEmpty() ? "nothing written"
                        : kept.size() <= 3 ? "wrote only " + String.join(", ", kept.stream().map(Object::toString).toList())
                        : "wrote only " + kept.size() + " files, the last " + kept.get(kept.size() - 1)));
                err.flush();
            }
        }, "say interrupted"));
    }

    /** Whether the JVM is shutting down: it then refuses a new shutdown hook. */
    private static boolean shuttingDown() {
        Thread probe = new Thread(() -> { });
        try {
            Runtime.getRuntime().addShutdownHook(probe);
            Runtime.getRuntime().removeShutdownHook(probe);
            return false;
        } catch (IllegalStateException e) {
            return true;
        }
    }

    /** The subcommands, by name, in the order help lists them. */
    private static final Map<String, Class<?>> SUBCOMMANDS = new LinkedHashMap<>();

    static {
        SUBCOMMANDS.put("app", AppCommand.class);
        SUBCOMMANDS.put("wrap", WrapCommand.class);
        SUBCOMMANDS.put("view", ViewCommand.class);
        SUBCOMMANDS.put("fold", FoldCommand.class);
        SUBCOMMANDS.put("demo", DemoCommand.class);
        SUBCOMMANDS.put("refine", RefineCommand.class);
        SUBCOMMANDS.put("info", InfoCommand.class);
        SUBCOMMANDS.put("check", CheckCommand.class);
        SUBCOMMANDS.put("generate", GenerateCommand.class);
        SUBCOMMANDS.put("help", CommandLine.HelpCommand.class);
    }

    /** The command line with every subcommand. */
    public static CommandLine commandLine(PrintWriter out, PrintWriter err) {
        return commandLine(out, err, SUBCOMMANDS.keySet());
    }

    /**
     * The command line that {@code args} need. picocli reads the annotations of every command
     * it is given, over 100 ms for all of iFold's: a run of one subcommand needs only that
     * one, and {@code --version} none. Help, a misspelt name (for picocli's suggestions) and
     * anything else get them all.
     */
    static CommandLine commandLineFor(PrintWriter out, PrintWriter err, String[] args) {
        String first = null;
        boolean help = false;
        for (String arg : args) {
            if (!arg.startsWith("-")) {
                first = arg;
                break;
            }
            help |= arg.equals("-h") || arg.equals("--help");
        }
        if (first == null) {
            return commandLine(out, err, help ? SUBCOMMANDS.keySet() : List.of());
        }
        if (SUBCOMMANDS.containsKey(first) && !first.equals("help")) {
            return commandLine(out, err, List.of(first));
        }
        return commandLine(out, err, SUBCOMMANDS.keySet());
    }

    /** A command line with iFold's error handling: one line per error and a hint, never a stack trace. */
    private static CommandLine commandLine(PrintWriter out, PrintWriter err, Collection<String> subcommands) {
        CommandLine commandLine = new CommandLine(new Main());
        for (String name : subcommands) {
            commandLine.addSubcommand(name, SUBCOMMANDS.get(name));
        }
        // Every subcommand's help lists --version: each prints the program's, not nothing.
        versionEverywhere(commandLine, commandLine.getCommandSpec().version());
        commandLine.setOut(out);
        commandLine.setErr(err);
        commandLine.setParameterExceptionHandler((ex, args) -> {
            CommandLine cmd = ex.getCommandLine();
            cmd.getErr().println("ifold: " + usageError(ex));
            cmd.getErr().println("Try '" + cmd.getCommandSpec().qualifiedName() + " --help' for more.");
            cmd.getErr().flush();
            return cmd.getCommandSpec().exitCodeOnInvalidInput();
        });
        commandLine.setExecutionExceptionHandler((ex, cmd, parseResult) -> {
            if (AtomicFile.stopping()) {
                // Interrupted: what failed failed because iFold is stopping, and the shutdown says so in one line.
                return UserError.EXIT_CODE;
            }
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

    private static final Pattern NOT_A_NUMBER =
            Pattern.compile("Invalid value for option '([^']+)': '(.*)' is not an? (double|float|int|long)", Pattern.DOTALL);

    /**
     * What was wrong with what the user typed, in iFold's words: an option named as
     * {@code option --NAME: ...}, as every other check names it, and a misspelt option or
     * command with what it may have meant.
     */
    static String usageError(CommandLine.ParameterException ex) {
        if (ex instanceof CommandLine.UnmatchedArgumentException unmatched) {
            List<String> suggestions = unmatched.getSuggestions();
            String meant = suggestions.isEmpty() ? "" : ": did you mean " + String.join(" or ", suggestions) + "?";
            List<String> arguments = unmatched.getUnmatched();
            String first = arguments.isEmpty() ? "" : arguments.get(0);
            if (first.startsWith("-")) {
                return "unknown option '" + first + "'" + meant;
            }
            // Where commands are expected (ifold, ifold demo), a word is a misspelt one.
            boolean commands = !unmatched.getCommandLine().getSubcommands().isEmpty();
            return commands ? "unknown command '" + first + "'" + meant : "unexpected argument '" + first + "'";
        }
        Matcher number = NOT_A_NUMBER.matcher(ex.getMessage());
        if (number.matches()) {
            boolean whole = number.group(3).equals("int") || number.group(3).equals("long");
            String text = number.group(2);
            if (whole && text.strip().matches("[+-]?\\d+")) { // a whole number, beyond what the option holds
                return "option " + number.group(1) + ": '" + text + "' is out of range";
            }
            return "option " + number.group(1) + ": '" + text + "' is not " + (whole ? "a whole number" : "a number");
        }
        String message = ex.getMessage();
        return message.isEmpty() ? message : Character.toLowerCase(message.charAt(0)) + message.substring(1);
    }

    public static void main(String[] args) {
        System.setErr(new java.io.PrintStream(new JoglNoise(new java.io.BufferedOutputStream(new java.io.FileOutputStream(java.io.FileDescriptor.err))), true,
                java.nio.charset.Charset.defaultCharset()));
        PrintWriter out = new PrintWriter(System.out, true);
        PrintWriter err = new PrintWriter(System.err, true);
        sayWhenInterrupted(err);
        int code;
        try {
            code = commandLineFor(out, err, args).execute(args);
        } catch (OutOfMemoryError e) {
            // picocli passes Errors through; a model too big for the heap is still the user's to fix.
            err.println("ifold: out of memory: give the JVM more, e.g. JAVA_OPTS=-Xmx8g");
            code = UserError.EXIT_CODE;
        }
        // System.out swallows write errors: a full disk or a closed pipe under the summary is
        // still a run whose output was lost, not a success.
        if (out.checkError() && code == 0) {
            err.println("ifold: cannot write to the standard output (a full disk, or a pipe closed): its lines are lost");
            code = UserError.EXIT_CODE;
        }
        if (AtomicFile.stopping()) {
            // A signal is stopping the JVM, which halts with 128 + its number once the shutdown
            // hooks are done. Exiting here with the code the interrupted command returned would
            // race it: a nonzero exit once the hooks have run halts at once with its own status,
            // and a Ctrl-C came out as 1 instead of 130 about one run in four.
            waitForTheHalt();
        }
        ended = true;
        System.exit(code);
    }

    private static void waitForTheHalt() {
        while (true) {
            try {
                Thread.sleep(Long.MAX_VALUE);
            } catch (InterruptedException e) {
                // Only the halt ends this thread.
            }
        }
    }
}
