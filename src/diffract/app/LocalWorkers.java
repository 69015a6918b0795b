package diffract.app;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * Commands of this program run in at most {@code workers} separate Java processes at a time: the same Java, class path
 * (the jar, or the test run's classes), heap limit, class-data archive and disk cache as this one, each told it has its
 * share of the processors so that the workers together use the machine once, not {@code workers} times over. A worker
 * process ({@link WorkerCommand}) runs command after command, as they come: Java's start and the compilation of the
 * code they run are paid once per worker, not once per command; each command still writes its own files.
 */
final class LocalWorkers {
    /** How one command ended: its exit code, its output (standard output and error), and its wall time. */
    record Finished(int index, int exitCode, String output, double wallS) {
    }

    private static final com.fasterxml.jackson.databind.ObjectMapper JSON =
            new com.fasterxml.jackson.databind.ObjectMapper();

    private LocalWorkers() {
    }

    /** A worker's share of this machine's processors when {@code workers} run at once: at least 1. */
    static int share(int workers) {
        return Math.max(1, Runtime.getRuntime().availableProcessors() / workers);
    }

    /**
     * Runs every argument list (a command of {@link Main}) in {@code workers} worker processes, each told it has
     * {@code processors} processors ({@link #share} of them by default), each taking the next command in order when it
     * has ended one; {@code finished} hears of each as it ends, with its wall time (a worker's first command's
     * includes the worker's start). The first failure stops the workers and is returned; else null.
     */
    static Finished run(List<List<String>> commands, int workers, int processors, Consumer<Finished> finished)
            throws IOException, InterruptedException {
        return run(commands, java.util.stream.IntStream.range(0, commands.size()).toArray(), workers, processors,
                finished);
    }

    /**
     * As {@link #run(List, int, int, Consumer)}, the commands handed out in {@code order} (indices into
     * {@code commands}, each once); a {@link Finished}'s index is the command's own.
     */
    static Finished run(List<List<String>> commands, int[] order, int workers, int processors,
                        Consumer<Finished> finished) throws IOException, InterruptedException {
        if (order.length != commands.size()
                || java.util.stream.IntStream.of(order).distinct().filter(i -> i >= 0 && i < order.length).count()
                != order.length) {
            throw new IllegalArgumentException("the order must name every command once: " + Arrays.toString(order));
        }
        List<String> worker = new ArrayList<>(javaCommand(processors));
        worker.add("worker");
        ExecutorService pool = Executors.newFixedThreadPool(workers, r -> {
            Thread t = new Thread(r, "local-worker");
            t.setDaemon(true);
            return t;
        });
        List<Process> started = java.util.Collections.synchronizedList(new ArrayList<>());
        AtomicInteger next = new AtomicInteger();
        Finished[] failure = new Finished[1];
        try {
            List<Future<?>> futures = new ArrayList<>();
            for (int w = 0; w < workers; w++) {
                futures.add(pool.submit(() -> {
                    work(worker, commands, order, next, started, failure, finished);
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

    /** One worker process: the next command, until none is left or one has failed; then its input ends, and so does it. */
    private static void work(List<String> worker, List<List<String>> commands, int[] order, AtomicInteger next,
                             List<Process> started, Finished[] failure, Consumer<Finished> finished)
            throws IOException, InterruptedException {
        long start = System.nanoTime();
        Process p = new ProcessBuilder(worker).redirectErrorStream(true).start();
        started.add(p);
        try (BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
             Writer in = new OutputStreamWriter(p.getOutputStream(), StandardCharsets.UTF_8)) {
            for (int taken = next.getAndIncrement(); taken < order.length; taken = next.getAndIncrement()) {
                int index = order[taken];
                synchronized (failure) {
                    if (failure[0] != null) {
                        return; // a command failed: start no more
                    }
                }
                in.write(JSON.writeValueAsString(commands.get(index)) + "\n");
                in.flush();
                StringBuilder output = new StringBuilder();
                Integer code = null;
                for (String line = out.readLine(); line != null; line = out.readLine()) {
                    if (line.startsWith(WorkerCommand.DONE)) {
                        code = Integer.parseInt(line.substring(WorkerCommand.DONE.length()).trim());
                        break;
                    }
                    output.append(line).append('\n');
                }
                if (code == null) { // the worker ended amid the command: its exit code, and never 0
                    int exit = p.waitFor();
                    code = exit == 0 ? 1 : exit;
                }
                Finished f = new Finished(index, code, output.toString(), (System.nanoTime() - start) * 1e-9);
                start = System.nanoTime();
                synchronized (failure) {
                    if (failure[0] != null) {
                        return; // stopped because another failed: that one is the news
                    }
                    if (f.exitCode() != 0) {
                        failure[0] = f;
                        started.forEach(Process::destroy);
                    }
                    finished.accept(f);
                }
                if (f.exitCode() != 0) {
                    return;
                }
            }
        } catch (IOException e) {
            synchronized (failure) {
                if (failure[0] != null) {
                    return; // the pipe closed because another failed and the workers were stopped
                }
            }
            throw e;
        }
        p.waitFor();
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
