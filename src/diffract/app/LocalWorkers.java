package diffract.app;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;

/**
 * Commands of this program run as separate Java processes, at most {@code workers} at a time: the same Java, class path
 * (the jar, or the test run's classes), heap limit, class-data archive and disk cache as this one, each told it has its
 * share of the processors so that the workers together use the machine once, not {@code workers} times over.
 */
final class LocalWorkers {
    /** How one process ended: its exit code, its output (standard output and error), and its wall time. */
    record Finished(int index, int exitCode, String output, double wallS) {
    }

    private LocalWorkers() {
    }

    /** A worker's share of this machine's processors when {@code workers} run at once: at least 1. */
    static int share(int workers) {
        return Math.max(1, Runtime.getRuntime().availableProcessors() / workers);
    }

    /**
     * Runs every argument list (a command of {@link Main}), {@code workers} at a time, in order, each worker told it
     * has {@code processors} processors ({@link #share} of them by default); {@code finished} hears of each as it
     * ends. The first failure stops those still running and is returned; else null.
     */
    static Finished run(List<List<String>> commands, int workers, int processors, Consumer<Finished> finished)
            throws IOException, InterruptedException {
        List<String> prefix = javaCommand(processors);
        ExecutorService pool = Executors.newFixedThreadPool(workers, r -> {
            Thread t = new Thread(r, "local-worker");
            t.setDaemon(true);
            return t;
        });
        List<Process> started = java.util.Collections.synchronizedList(new ArrayList<>());
        Finished[] failure = new Finished[1];
        try {
            List<Future<?>> futures = new ArrayList<>();
            for (int i = 0; i < commands.size(); i++) {
                int index = i;
                futures.add(pool.submit(() -> {
                    synchronized (failure) {
                        if (failure[0] != null) {
                            return null; // a piece failed: start no more
                        }
                    }
                    List<String> command = new ArrayList<>(prefix);
                    command.addAll(commands.get(index));
                    long start = System.nanoTime();
                    Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
                    started.add(p);
                    String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
                    Finished f = new Finished(index, p.waitFor(), output, (System.nanoTime() - start) * 1e-9);
                    synchronized (failure) {
                        if (failure[0] != null) {
                            return null; // stopped because another failed: that one is the news
                        }
                        if (f.exitCode() != 0) {
                            failure[0] = f;
                            started.forEach(Process::destroy);
                        }
                        finished.accept(f);
                    }
                    return null;
                }));
            }
            for (Future<?> f : futures) {
                try {
                    f.get();
                } catch (ExecutionException e) {
                    if (e.getCause() instanceof IOException io) {
                        throw io;
                    }
                    throw new IllegalStateException(e.getCause());
                }
            }
        } finally {
            started.forEach(Process::destroy); // an interrupted submit leaves no worker behind
            pool.shutdownNow();
        }
        return failure[0];
    }

    /** java, its options as this process was given them where they matter to a worker, the class path and Main. */
    private static List<String> javaCommand(int processors) {
        List<String> command = new ArrayList<>(javaVm(true));
        command.add("-XX:ActiveProcessorCount=" + processors);
        command.addAll(mainClass());
        return command;
    }

    /**
     * This process' java and its options that matter to a worker: the heap (DIFFRACT_JAVA_OPTS), ./diffract's
     * class-data archive, headless AWT, the disk cache's size limit and, with {@code cacheFolder}, its folder (not
     * agents or debuggers).
     */
    static List<String> javaVm(boolean cacheFolder) {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (option.startsWith("-Xmx") || option.startsWith("-Xms") || option.startsWith("-Xss")
                    || option.startsWith("-XX:SharedArchiveFile=") || option.equals("-Xlog:disable")) {
                command.add(option);
            }
        }
        List<String> properties = cacheFolder ? List.of(diffract.util.DiskCache.ROOT_PROPERTY,
                diffract.util.DiskCache.LIMIT_PROPERTY, "java.awt.headless")
                : List.of(diffract.util.DiskCache.LIMIT_PROPERTY, "java.awt.headless");
        for (String property : properties) {
            String value = System.getProperty(property);
            if (value != null) {
                command.add("-D" + property + "=" + value);
            }
        }
        return command;
    }

    /** The class path of this process and the program's entry point, which take a command's arguments. */
    static List<String> mainClass() {
        return List.of("-cp", System.getProperty("java.class.path"), Main.class.getName());
    }
}
