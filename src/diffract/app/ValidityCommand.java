package diffract.app;

import diffract.app.options.CacheOption;
import diffract.app.options.QuietOption;
import diffract.bench.ValidityMap;
import diffract.bench.ValidityReport;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

/**
 * {@code diffract validity}: the validity map of the scalar model against the rigorous method ({@link ValidityMap}),
 * into a folder: {@code validity.csv} (written after every case, so an interrupted run keeps what it measured and a
 * rerun into the same folder measures only the rest), {@code validity.md} and {@code images/validity-RELIEF.png}.
 */
@Command(name = "validity", mixinStandardHelpOptions = true)
final class ValidityCommand implements Callable<Integer> {
    @Option(names = {"-o", "--output"}, paramLabel = "DIR") Path outputDir;

    @Option(names = "--quick") boolean quick;

    @Mixin QuietOption quiet;
    @Mixin CacheOption cache;

    @Override
    public Integer call() throws IOException {
        if (outputDir == null) {
            throw new UserInputException("validity needs -o DIR, the folder for validity.csv, validity.md and its "
                    + "images");
        }
        OutputPaths.require(OutputPaths.folder("-o", outputDir));
        Reporter reporter = quiet.reporter();
        List<ValidityMap.Case> cases = quick ? quickGrid() : ValidityMap.grid();
        Path csv = outputDir.resolve("validity.csv");
        List<ValidityMap.Result> results = new ArrayList<>();
        if (Files.isRegularFile(csv)) {
            for (ValidityMap.Result r : ValidityReport.read(Files.readString(csv, StandardCharsets.UTF_8))) {
                if (cases.contains(r.c())) {
                    results.add(r);
                }
            }
            if (!results.isEmpty()) {
                reporter.info(results.size() + " of " + cases.size() + " cases read from " + csv);
            }
        }
        String command = "diffract validity" + (quick ? " --quick" : "") + " -o " + outputDir;
        Files.createDirectories(outputDir);
        long start = System.nanoTime();
        int done = results.size();
        for (ValidityMap.Case c : cases) {
            if (results.stream().anyMatch(r -> r.c().equals(c))) {
                continue;
            }
            ValidityMap.Result r = ValidityMap.measure(c, Reporter.SILENT);
            results.add(r);
            done++;
            reporter.info(String.format(Locale.ROOT, "%d/%d %s: CIEDE2000 %.2f (Stam's gain %.2f), orders %+.0f %%",
                    done, cases.size(), c.label(), r.deltaE(), r.deltaEStam(), 100 * r.orderError()));
            reporter.progress("validity map", done / (double) cases.size());
            Files.writeString(csv, ValidityReport.csv(results, command), StandardCharsets.UTF_8);
        }
        Files.writeString(csv, ValidityReport.csv(results, command), StandardCharsets.UTF_8);
        List<Path> images = ValidityReport.heatMaps(results, outputDir.resolve("images"));
        double seconds = (System.nanoTime() - start) * 1e-9;
        Files.writeString(outputDir.resolve("validity.md"), ValidityReport.markdown(results, images, outputDir,
                command, seconds), StandardCharsets.UTF_8);
        System.out.printf(Locale.ROOT, "validity: %d cases in %.0f s%nwrote %s, %s and %d images%n", results.size(),
                seconds, csv, outputDir.resolve("validity.md"), images.size());
        return 0;
    }

    /** A few cases on each side of the boundary, for a check of the whole path in seconds. */
    static List<ValidityMap.Case> quickGrid() {
        return List.of(new ValidityMap.Case(ValidityMap.Family.SINUSOID, 2.5, 0.025, 0),
                new ValidityMap.Case(ValidityMap.Family.SINUSOID, 0.65, 0.1, 30),
                new ValidityMap.Case(ValidityMap.Family.ELAPHE_RIDGE, 1.144, 0.3, 30));
    }
}
