package diffract.app;

import diffract.jrtr.GLInfo;
import diffract.jrtr.HeadlessGL;
import diffract.precompute.TaylorTermComputer;
import diffract.util.UserInputException;
import diffract.util.Version;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./diffract}: the command line. Every command answers {@code --help}; bad usage or input ends with a
 * one-line message and exit code 2, without a stack trace unless {@code --debug} is given.
 */
@Command(name = "diffract", mixinStandardHelpOptions = true, version = "diffract " + Version.VERSION,
        description = "Structural colour from natural diffraction gratings (Single 2014, after Stam 1999).",
        subcommands = {DemoCommand.class, PrecomputeCommand.class, BrdfMapCommand.class, CompareCommand.class,
                ConvertTermsCommand.class, PatchCommand.class, ViewCommand.class, RenderCommand.class, WarmUpCommand.class, BenchCommand.class,
                CommandLine.HelpCommand.class})
public final class Main implements Runnable {
    /** Exit code for bad usage or bad input. */
    public static final int EXIT_USAGE = 2;

    @Option(names = "--debug", scope = CommandLine.ScopeType.INHERIT,
            description = "Show stack traces of errors.")
    boolean debug;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "missing command: try 'diffract --help'");
    }

    public static void main(String[] args) {
        int code = execute(args);
        TaylorTermComputer.shutdownThreadPool();
        System.exit(code);
    }

    /** Runs the command line and returns the exit code (tests call this). */
    public static int execute(String... args) {
        CommandLine cli = new CommandLine(new Main());
        reportGlOncePerRenderer(System.err);
        HeadlessGL.useGpu(null); // --gpu, where given, applies to this command only
        boolean debug = java.util.Arrays.asList(args).contains("--debug");
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            if (debug) {
                ex.printStackTrace();
            }
            if (ex instanceof UserInputException) {
                System.err.println("diffract: " + ex.getMessage());
                return EXIT_USAGE;
            }
            System.err.println("diffract: internal error: " + ex + (debug ? "" : " (run with --debug for details)"));
            return 1;
        });
        cli.setParameterExceptionHandler((ex, args1) -> {
            System.err.println("diffract: " + ex.getMessage());
            System.err.println("try '" + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help'");
            return EXIT_USAGE;
        });
        return cli.execute(args);
    }

    /** Every GPU command says once which OpenGL it draws with (vendor, renderer, version, platform). */
    private static void reportGlOncePerRenderer(java.io.PrintStream err) {
        java.util.Set<String> seen = java.util.concurrent.ConcurrentHashMap.newKeySet();
        GLInfo.reportTo(info -> {
            if (seen.add(info.toString())) {
                err.println("diffract: " + info);
            }
        });
    }
}
