package diffract.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import diffract.app.options.BrdfOptions;
import diffract.app.options.PatchOptions;
import diffract.app.options.QuietOption;
import diffract.optics.BrdfSettings;
import diffract.optics.Methods;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.rigorous.Resolution;
import diffract.optics.validity.OrderComparison;
import diffract.pipeline.NamedPatch;
import diffract.scene.LightDirection;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

/**
 * {@code diffract orders}: the reflected diffraction orders of a 1-D patch, their efficiencies from Maxwell's
 * equations (the rigorous method) beside the scalar model's, per wavelength; with {@code --convergence} how much they
 * move with more harmonics and a finer staircase.
 */
@Command(name = "orders", mixinStandardHelpOptions = true, abbreviateSynopsis = true)
final class OrdersCommand implements Callable<Integer> {
    @Mixin PatchOptions patch;
    @Mixin BrdfOptions brdf;
    @Mixin QuietOption quiet;

    @Option(names = "--theta-i", defaultValue = "30", paramLabel = "DEG") double thetaIDeg;

    @Option(names = "--phi-i", paramLabel = "DEG") Double phiIDeg;

    @Option(names = "--lambdas", paramLabel = "NM[,NM...]", split = ",", defaultValue = "450,550,650")
    List<Double> lambdasNm;

    @Option(names = "--convergence") boolean convergence;

    @Option(names = "--json", paramLabel = "FILE.json") Path json;

    @Override
    public Integer call() throws IOException {
        patch.validateRequired();
        brdf.validate();
        if (brdf.auto()) {
            throw new UserInputException("--variant auto chooses among the GPU methods; orders compares the rigorous "
                    + "method with the scalar model: drop --variant");
        }
        if (!(thetaIDeg >= 0 && thetaIDeg <= LightDirection.MAX_THETA_DEG)) {
            throw new UserInputException("--theta-i must be in [0, " + LightDirection.MAX_THETA_DEG_TEXT
                    + "] degrees, got " + thetaIDeg);
        }
        for (double l : lambdasNm) {
            if (!(l >= 200 && l <= 2000)) {
                throw new UserInputException("--lambdas takes wavelengths in nm within [200, 2000], got " + l);
            }
        }
        if (json != null) {
            OutputPaths.requireWritableFile(json, "--json", "orders.json", ".json");
        }
        BrdfSettings settings = brdf.apply(BrdfSettings.thesis(Methods.Role.EXACT.method()));
        Reporter reporter = quiet.reporter();
        NamedPatch named = patch.load("", reporter);
        HeightField field = named.meanSubtracted();
        OrderComparison.refusal(field).ifPresent(why -> {
            throw new UserInputException(named.name() + ": " + why + "; its ridges' cross-section is a 1-D patch "
                    + "(e.g. --synthetic elaphe-ridge for the Elaphe-like skin)");
        });
        double phi = phiIDeg != null ? phiIDeg : patch.periodAzimuthDeg("");
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, phi);
        System.out.printf(Locale.ROOT, "%s: %s%n", named.name(), OrderComparison.describe(field));
        System.out.printf(Locale.ROOT, "light at theta_i %s, phi_i %s degrees, %s; index %s; scalar model: gain %s%n",
                num(thetaIDeg), num(phi), settings.rigorous().polarisation().label(), settings.illumination().material(),
                settings.illumination().gain().label());
        List<Map<String, Object>> out = new ArrayList<>();
        for (double lambdaNm : lambdasNm) {
            OrderComparison c = OrderComparison.of(field, settings, wi, lambdaNm);
            OrderComparison finer = convergence ? OrderComparison.of(field, refined(settings, c), wi, lambdaNm) : null;
            print(c, finer);
            out.add(json(c, finer));
        }
        if (json != null) {
            Map<String, Object> root = new LinkedHashMap<>();
            root.put("patch", named.name());
            root.put("structure", OrderComparison.describe(field));
            root.put("thetaIDeg", thetaIDeg);
            root.put("phiIDeg", phi);
            root.put("refractiveIndex", settings.illumination().material().toString());
            root.put("polarisation", settings.rigorous().polarisation().label());
            root.put("scalarGain", settings.illumination().gain().label());
            root.put("wavelengths", out);
            new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT).writeValue(json.toFile(), root);
            System.out.println("wrote " + json);
        }
        return 0;
    }

    /** The settings of {@code c}'s solve with half as many harmonics again (at least 4 more) and twice the layers. */
    private static BrdfSettings refined(BrdfSettings settings, OrderComparison c) {
        Resolution r = settings.rigorous().resolution();
        int finerM = Math.min(Resolution.MAX_ORDER, Math.max(c.maxOrder() + 4, (int) Math.round(1.5 * c.maxOrder())));
        Resolution finer = new Resolution(finerM, Math.min(Resolution.MAX_LAYERS, 2 * r.layers()), r.extrapolate());
        return settings.with(b -> b.rigorous(settings.rigorous().withResolution(finer)));
    }

    private static void print(OrderComparison c, OrderComparison finer) {
        System.out.printf(Locale.ROOT, "%n%.1f nm: rigorous R = %.5f, T = %.5f, R + T = %.9f (harmonics -%d..%d, %d "
                + "layers%s)%n", c.lambdaNm(), c.reflected(), c.transmitted(), c.reflected() + c.transmitted(),
                c.maxOrder(), c.maxOrder(), c.layers(), finer != null ? String.format(Locale.ROOT,
                "; finer: -%d..%d, %d layers", finer.maxOrder(), finer.maxOrder(), finer.layers()) : "");
        System.out.printf(Locale.ROOT, "  %5s %8s %10s %10s %10s %10s %8s%s%n", "order", "theta_r", "rigorous s",
                "rigorous p", "rigorous", "scalar", "error", finer != null ? "   finer: change" : "");
        for (OrderComparison.Order o : c.orders()) {
            String change = "";
            if (finer != null) {
                double f = finer.orders().stream().filter(x -> x.order() == o.order()).mapToDouble(
                        OrderComparison.Order::rigorous).findFirst().orElse(Double.NaN);
                change = String.format(Locale.ROOT, "   %+.2e", f - o.rigorous());
            }
            System.out.printf(Locale.ROOT, "  %+5d %7.2f° %10.6f %10.6f %10.6f %10.6f %+7.1f%%%s%n", o.order(),
                    Math.copySign(o.thetaDeg(), o.x() + o.y()), o.rigorousS(), o.rigorousP(), o.rigorous(), o.scalar(),
                    100 * o.relativeError(), change);
        }
    }

    private static Map<String, Object> json(OrderComparison c, OrderComparison finer) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("lambdaNm", c.lambdaNm());
        m.put("reflected", c.reflected());
        m.put("transmitted", c.transmitted());
        List<Map<String, Object>> orders = new ArrayList<>();
        for (OrderComparison.Order o : c.orders()) {
            Map<String, Object> row = new LinkedHashMap<>();
            row.put("order", o.order());
            row.put("texel", List.of(o.texelX(), o.texelY()));
            row.put("direction", List.of(o.x(), o.y()));
            row.put("rigorousS", o.rigorousS());
            row.put("rigorousP", o.rigorousP());
            row.put("rigorous", o.rigorous());
            row.put("scalar", o.scalar());
            if (finer != null) {
                finer.orders().stream().filter(x -> x.order() == o.order()).findFirst()
                        .ifPresent(f -> row.put("rigorousFiner", f.rigorous()));
            }
            orders.add(row);
        }
        m.put("orders", orders);
        return m;
    }

    private static String num(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
