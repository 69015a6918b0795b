package diffract.app;

import diffract.app.options.CacheOption;
import diffract.app.options.OptionNames;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.contexts.HeadlessGL;
import diffract.optics.settings.InvalidSettingException;
import diffract.precompute.TaylorTermComputer;
import diffract.util.DiskCache;
import diffract.util.UserInputException;
import diffract.util.Version;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine;

/**
 * {@code ./diffract}: the command line. Every command answers {@code --help}; bad usage or input ends with a
 * one-line message and exit code 2, without a stack trace unless {@code --debug} is given.
 */
@Command(name = "diffract", mixinStandardHelpOptions = true, version = "diffract " + Version.VERSION,
        resourceBundle = "diffract.app.HelpText")
public final class Main implements Runnable {
    /** Exit code for bad usage or bad input. */
    public static final int EXIT_USAGE = 2;

    /**
     * The commands, in the order help lists them. They are registered by {@link #commandLine}, not by the
     * annotation, so that a run of one command builds only that command's options: picocli reads every option of
     * every command it is given, and for all of them that is about a fifth of a second of each process' start.
     */
    private static final java.util.Map<String, java.util.function.Supplier<Object>> COMMANDS = commands();

    private static java.util.Map<String, java.util.function.Supplier<Object>> commands() {
        java.util.Map<String, java.util.function.Supplier<Object>> c = new java.util.LinkedHashMap<>();
        c.put("demo", DemoCommand::new);
        c.put("precompute", PrecomputeCommand::new);
        c.put("brdfmap", BrdfMapCommand::new);
        c.put("compare", CompareCommand::new);
        c.put("orders", OrdersCommand::new);
        c.put("validity", ValidityCommand::new);
        c.put("convert-terms", ConvertTermsCommand::new);
        c.put("patch", PatchCommand::new);
        c.put("channels", ChannelsCommand::new);
        c.put("view", ViewCommand::new);
        c.put("render", RenderCommand::new);
        c.put("measure", MeasureCommand::new);
        c.put("warm-up", WarmUpCommand::new);
        c.put("bench", BenchCommand::new);
        c.put("export", ExportCommand::new);
        c.put("merge", MergeCommand::new);
        c.put("submit", SubmitCommand::new);
        c.put("worker", WorkerCommand::new);
        c.put("help", CommandLine.HelpCommand::new);
        return java.util.Collections.unmodifiableMap(c);
    }

    /** The whole command line: every command (help, tests, and the commands that parse another's options). */
    public static CommandLine commandLine() {
        return commandLine(COMMANDS.keySet());
    }

    /**
     * The command line for {@code args}: where its first word names a command (other than help), that command
     * alone; else every command, for the help, the list of commands and the suggestions that name the others.
     */
    static CommandLine commandLine(String... args) {
        for (String arg : args) {
            if (!arg.startsWith("-")) {
                return COMMANDS.containsKey(arg) && !arg.equals("help") ? commandLine(java.util.List.of(arg))
                        : commandLine();
            }
        }
        return commandLine();
    }

    private static CommandLine commandLine(java.util.Collection<String> names) {
        CommandLine cli = new CommandLine(new Main());
        for (String name : names) {
            cli.addSubcommand(COMMANDS.get(name).get()); // named by its @Command
            if (!cli.getSubcommands().containsKey(name)) {
                throw new IllegalStateException("the command registered as " + name + " names itself otherwise");
            }
        }
        cli.setCaseInsensitiveEnumValuesAllowed(true); // after the commands: it applies to those registered
        if (names.contains("patch")) {
            cli.getSubcommands().get("patch").getCommandSpec().usageMessage().footer(PatchCommand.catalogueText());
        }
        return cli;
    }

    @Option(names = "--debug", scope = CommandLine.ScopeType.INHERIT) boolean debug;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        java.util.List<String> commands = spec.subcommands().entrySet().stream()
                .filter(e -> !e.getValue().getCommandSpec().usageMessage().hidden() && !e.getKey().equals("help"))
                .map(java.util.Map.Entry::getKey).toList();
        throw new CommandLine.ParameterException(spec.commandLine(), "missing command: one of "
                + String.join(", ", commands));
    }

    public static void main(String[] args) {
        int code = execute(args);
        TaylorTermComputer.shutdownThreadPool();
        System.exit(code);
    }

    /** Runs the command line and returns the exit code (tests call this). */
    public static int execute(String... args) {
        CommandLine cli = commandLine(args);
        reportGlOncePerRenderer(System.err);
        HeadlessGL.useGpu(null); // --gpu, where given, applies to this command only
        boolean debug = java.util.Arrays.asList(args).contains("--debug");
        cli.setExecutionExceptionHandler((ex, commandLine, parseResult) -> failure(ex, debug));
        cli.setParameterExceptionHandler((ex, args1) -> {
            System.err.println("diffract: " + ex.getMessage() + "; try '"
                    + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help'");
            return EXIT_USAGE;
        });
        cli.setExecutionStrategy(parseResult -> {
            CommandLine.ParseResult command = parseResult;
            while (command.hasSubcommand()) {
                command = command.subcommand();
            }
            DiskCache.useDisk(!command.hasMatchedOption(CacheOption.FLAG)); // --no-cache: for this command only
            return new CommandLine.RunLast().execute(parseResult);
        });
        boolean diskBefore = DiskCache.diskInUse();
        try {
            return cli.execute(args);
        } catch (OutOfMemoryError | StackOverflowError e) { // picocli passes errors through: the last line of defence
            return failure(e, debug);
        } finally {
            DiskCache.useDisk(diskBefore); // a command run by another one leaves the other's choice as it was
        }
    }

    /**
     * One line for what ended a command, and its exit code: the user's input (or the machine's limits) 2, a bug 1.
     * Causes are searched, so a failure inside a worker thread reads the same as one in the command's own.
     */
    static int failure(Throwable ex, boolean debug) {
        if (debug) {
            ex.printStackTrace();
        }
        InvalidSettingException setting = cause(ex, InvalidSettingException.class);
        if (setting != null) { // the settings name the quantity; the command line names the option that gives it
            System.err.println("diffract: " + OptionNames.of(setting.quantity()) + ": " + setting.getMessage());
            return EXIT_USAGE;
        }
        UserInputException input = cause(ex, UserInputException.class);
        if (input != null) {
            System.err.println("diffract: " + input.getMessage());
            return EXIT_USAGE;
        }
        if (cause(ex, OutOfMemoryError.class) != null) {
            long maxGiB = Math.max(1, Runtime.getRuntime().maxMemory() >> 30);
            System.err.printf(java.util.Locale.ROOT, "diffract: out of memory: the work needs more than the Java heap's"
                    + " %d GB; make it smaller (a smaller --size, fewer --terms, a cropped patch) or give Java a larger"
                    + " heap: DIFFRACT_JAVA_OPTS=-Xmx%dg ./diffract ...%n", maxGiB, 2 * maxGiB);
            return EXIT_USAGE;
        }
        if (cause(ex, StackOverflowError.class) != null) {
            System.err.println("diffract: the input nests too deeply to process (stack overflow)"
                    + (debug ? "" : "; run with --debug for details"));
            return EXIT_USAGE;
        }
        java.io.IOException io = cause(ex, java.io.IOException.class);
        if (io != null) {
            System.err.println("diffract: " + describe(io));
            return EXIT_USAGE;
        }
        System.err.println("diffract: internal error: " + ex + (debug ? "" : " (run with --debug for details)"));
        return 1;
    }

    /** An I/O failure in words: NIO's own messages are often only the path. */
    static String describe(java.io.IOException e) {
        if (e instanceof java.nio.file.AccessDeniedException a) {
            return "permission denied: " + a.getFile();
        }
        if (e instanceof java.nio.file.NoSuchFileException n) {
            return "no such file or folder: " + n.getFile();
        }
        if (e instanceof java.nio.file.FileAlreadyExistsException f) {
            return "already exists: " + f.getFile();
        }
        if (e instanceof java.nio.file.FileSystemException f) {
            return "cannot use " + f.getFile() + (f.getReason() != null ? ": " + f.getReason() : "");
        }
        return "input/output error: " + e.getMessage();
    }

    private static <T extends Throwable> T cause(Throwable ex, Class<T> type) {
        for (Throwable t = ex; t != null; t = t.getCause() == t ? null : t.getCause()) {
            if (type.isInstance(t)) {
                return type.cast(t);
            }
        }
        return null;
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
