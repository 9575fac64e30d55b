/**
 * The command line: a thin shell of picocli subcommands over the core. Every subcommand is a
 * {@code Callable<Integer>}; only {@link ifold.cli.Main#main} calls {@code System.exit}. Bad
 * input ends in one line on stderr and a non-zero exit, never a stack trace.
 */
package ifold.cli;
