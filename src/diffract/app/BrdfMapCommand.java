package diffract.app;

import diffract.colour.ColourPath;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.CoherenceWindow;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.HeightField;
import diffract.optics.TaylorEvaluation;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.io.SamplingCheck;
import diffract.jrtr.FloatTextureArray;
import diffract.render.DiffractionShaders;
import diffract.render.GpuBrdfMap;
import diffract.render.TermFormats;
import diffract.bench.AutoChoice;
import diffract.precompute.Precomputation;
import diffract.precompute.TaylorTermComputer;
import diffract.precompute.TermFolders;
import diffract.precompute.ThesisFormat;
import diffract.bench.AutoCalibration;
import diffract.util.ImageFiles;
import diffract.util.OutputPaths;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code diffract brdfmap}: the BRDF of a patch for one light direction, over all viewing directions. */
@Command(name = "brdfmap", mixinStandardHelpOptions = true,
        description = {"Render a BRDF map: pixel (i, j) of the S x S map is the viewing direction",
                "(x, y, sqrt(1 - x^2 - y^2)), x = 2(i + 0.5)/S - 1, y = 1 - 2(j + 0.5)/S; outside the unit disk is black.",
                "The tangent frame's x axis runs along the height field's columns, y along its rows."})
final class BrdfMapCommand implements Callable<Integer> {
    @Mixin
    GpuOption gpu;

    @Mixin
    PatchInput input;

    @Mixin
    QuietOption quiet;

    @Option(names = "--theta-i", required = true, paramLabel = "DEG", description = "Polar angle of the light direction.")
    double thetaIDeg;

    @Option(names = "--phi-i", defaultValue = "0", paramLabel = "DEG", description = "Azimuth of the light (default ${DEFAULT-VALUE}).")
    double phiIDeg;

    @Option(names = "--lambda", paramLabel = "NM", description = "Monochromatic map of the relative BRDF at this wavelength (grey).")
    Double lambdaNm;

    @Option(names = "--variant", defaultValue = "reference", paramLabel = "V",
            description = "reference (exact), flss, nmm, pq, baked (GPU table of flss), or auto: the cheapest GPU "
                    + "configuration whose measured error on this patch meets --max-delta-e (default ${DEFAULT-VALUE}).")
    String variant;

    @Option(names = "--max-delta-e", paramLabel = "DE",
            description = "With --variant auto: the accuracy target, mean CIEDE2000 against the reference over the lit pixels.")
    Double maxDeltaE;

    @Option(names = "--terms", defaultValue = "30", paramLabel = "N", description = "Highest Taylor order N for flss/nmm/pq (default ${DEFAULT-VALUE}).")
    int highestOrder;

    @Option(names = "--window-radius", defaultValue = "1", paramLabel = "R|auto",
            description = "Window of (2R+1)^2 texels for flss/nmm/pq/baked (default ${DEFAULT-VALUE}); auto: per axis "
                    + "the smallest R capturing 99.73 % of the Gaussian window's weight (sigma_f in texels).")
    String windowRadiusText;

    @Option(names = "--taylor-tolerance", defaultValue = "0", paramLabel = "EPS",
            description = "Stop each lookup's Taylor loop at the first order whose Lagrange bound x^(n+1) e^x/(n+1)! "
                    + "(x = k|w|max|h|) is <= EPS; 0 = always --terms (default ${DEFAULT-VALUE}).")
    double taylorTolerance;

    @Option(names = "--baked-samples", defaultValue = "0,0", paramLabel = "UV,W",
            description = "baked: table samples along u and v (each) and along w; 0 = automatic (default ${DEFAULT-VALUE}).")
    String bakedSamplesText;

    @Option(names = "--lambda-step", defaultValue = "5", paramLabel = "NM", description = "Wavelength step of flss/pq, nmm's fallback (default ${DEFAULT-VALUE}).")
    double lambdaStepNm;

    @Option(names = "--lambda-min", defaultValue = "380", paramLabel = "NM", description = "Default ${DEFAULT-VALUE}.")
    double lambdaMinNm;

    @Option(names = "--lambda-max", defaultValue = "780", paramLabel = "NM", description = "Default ${DEFAULT-VALUE}.")
    double lambdaMaxNm;

    @Option(names = "--coherence-length", defaultValue = "65", paramLabel = "UM", description = "4 sigma_s of the coherence window (default ${DEFAULT-VALUE}).")
    double coherenceLengthUm;

    @Option(names = "--refractive-index", defaultValue = "1.5", paramLabel = "N", description = "For Schlick's Fresnel term (default ${DEFAULT-VALUE}).")
    double refractiveIndex;

    @Option(names = "--pq-replicas", defaultValue = "0", paramLabel = "R", description = "PQ replicas per axis; 0 spans the coherence length.")
    int pqReplicas;

    @Option(names = "--terms-dir", paramLabel = "DIR",
            description = "Use precomputed terms instead of the cache: diffract's format or the thesis' Octave format (detected).")
    Path termsDir;

    @Option(names = "--terms-height-unit", defaultValue = "auto", paramLabel = "UNIT",
            description = "Heights' unit of a --terms-dir from the thesis' script: auto, m or um (default ${DEFAULT-VALUE}).")
    String termsHeightUnit;

    @Option(names = "--size", defaultValue = "256", paramLabel = "S", description = "Map size in pixels (default ${DEFAULT-VALUE}).")
    int size;

    @Option(names = "--exposure", defaultValue = "1", paramLabel = "E|auto",
            description = "Multiplies the linear values before display encoding (default ${DEFAULT-VALUE}); "
                    + "auto maps the brightest diffracted pixel (not the specular highlight) to 1. The PFM is never scaled.")
    String exposureText;

    @Option(names = "--colour", defaultValue = "srgb", paramLabel = "PATH",
            description = "srgb (IEC 61966-2-1, default) or thesis (the 2014 shader's CIE RGB matrix and gamma 2.5).")
    String colour;

    @Option(names = "--engine", paramLabel = "E",
            description = "cpu (default; gpu with --variant auto) or gpu: the GLSL shaders of flss, nmm and pq, rendered offscreen (OpenGL 3.3).")
    String engine;

    @Option(names = "--time", description = "With --engine gpu: print the median GPU time per frame (GL timer queries).")
    boolean time;

    @Option(names = "--texture-format", defaultValue = "rg32f", paramLabel = "F",
            description = "With --engine gpu: rg32f (default, exact), rg16f (half precision) or rg8 (the thesis' [0, 1]-normalised "
                    + "bytes, 003 eq. 1.1) Taylor-term textures.")
    String textureFormat;

    @Option(names = "--expansion", defaultValue = "auto", paramLabel = "E",
            description = {"Taylor expansion of flss/nmm/pq: auto (default: the thesis' series around 0 where the patch"
                    + " lets it reach 1e-3 in P, else around the nearest of several phase centres), plain or centred."
                    + " With --variant auto the default is plain: the path its calibration measured."})
    String expansion;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "MAP.png", description = "PNG to write.")
    Path output;

    @Option(names = "--pfm", paramLabel = "MAP.pfm", description = "Also write floats: linear sRGB (unclipped), or the relative BRDF with --lambda.")
    Path pfm;

    @Override
    public Integer call() throws IOException {
        if (size < 1 || size > 8192) {
            throw new UserInputException("--size must be between 1 and 8192, got " + size);
        }
        if (!(thetaIDeg >= 0 && thetaIDeg < 90)) {
            throw new UserInputException("--theta-i must be in [0, 90) degrees, got " + thetaIDeg);
        }
        if (lambdaNm != null && !(lambdaNm > 0)) {
            throw new UserInputException("--lambda must be > 0 nm, got " + lambdaNm);
        }
        ColourPath colourPath = parseColour(colour);
        fixedExposure(); // fail on a bad value now, not after minutes of work
        boolean auto = variant.trim().equalsIgnoreCase(AutoVariant.NAME);
        AutoVariant.checkOptions(auto, maxDeltaE, lambdaNm);
        boolean gpu = parseEngine(engine != null ? engine : auto ? "gpu" : "cpu");
        FloatTextureArray.Precision precision = TermFormats.parse(textureFormat);
        TaylorEvaluation.Mode expansionMode = TaylorEvaluation.Mode.parse(expansion);
        Variant named = auto ? null : Variant.parse(variant);
        if (gpu && named == Variant.REFERENCE) {
            throw new UserInputException(DiffractionShaders.REFERENCE_IS_CPU_ONLY);
        }
        if (named == Variant.BAKED && !gpu) {
            throw new UserInputException(DiffractionBrdf.BAKED_IS_GPU_ONLY);
        }
        if (named == Variant.BAKED && lambdaNm != null) {
            throw new UserInputException(GpuBrdfMap.BAKED_HAS_NO_MONOCHROMATIC);
        }
        if (time && !gpu) {
            throw new UserInputException("--time measures the GPU: add --engine gpu");
        }
        OutputPaths.requireWritableFile(output, "-o", "map.png");
        if (pfm != null) {
            OutputPaths.requireWritableFile(pfm, "--pfm", "map.pfm");
        }
        Reporter reporter = quiet.reporter();
        long start = System.nanoTime();
        HeightField field = input.load(reporter);
        boolean automaticWindow = windowRadiusText.trim().equalsIgnoreCase("auto");
        int[] bakedSamples = parseBakedSamples(bakedSamplesText);
        BrdfSettings settings = new BrdfSettings(auto ? Variant.FLSS : named, highestOrder,
                automaticWindow ? 1 : parseWindowRadius(windowRadiusText), lambdaMinNm, lambdaMaxNm, lambdaStepNm,
                coherenceLengthUm / 4.0, refractiveIndex, pqReplicas, taylorTolerance, automaticWindow,
                bakedSamples[0], bakedSamples[1], expansionMode);
        if (auto) { // the calibration computes reference maps of this patch
            MemoryCheck.brdfMap(field, settings.withVariant(Variant.REFERENCE), AutoCalibration.SIZE_PX, 0, null);
            AutoChoice choice = AutoVariant.choose(field, phiIDeg, settings, maxDeltaE, reporter);
            // auto's calibration measured the thesis' series at each N: its choice renders on that same path
            settings = choice.chosen().config().settings().withExpansion(
                    expansionMode == TaylorEvaluation.Mode.AUTO ? TaylorEvaluation.Mode.PLAIN : expansionMode);
            highestOrder = settings.highestOrder();
            precision = choice.chosen().config().precision();
            textureFormat = choice.chosen().config().textureFormat();
        }
        MemoryCheck.brdfMap(field, settings, size, thetaIDeg, lambdaNm);
        SamplingCheck.warnAboutAliasing(field, lambdaNm != null ? lambdaNm : lambdaMinNm,
                lambdaNm != null ? lambdaNm : lambdaMaxNm, thetaIDeg, reporter);
        TaylorTerms terms = null;
        if (settings.variant() != Variant.REFERENCE) {
            terms = termsDir != null
                    ? TermFolders.read(termsDir, ThesisFormat.HeightUnit.parse(termsHeightUnit), reporter)
                    : Precomputation.cached(new Precomputation.Request(field, input.patch.getFileName().toString(),
                    input.maxHeightUm, highestOrder, null, lambdaMinNm), reporter);
            if (terms.highestOrder() < highestOrder) {
                throw new UserInputException(termsDir + " holds terms 0.." + terms.highestOrder() + " but --terms "
                        + highestOrder + " was asked; pass --terms " + terms.highestOrder() + " or precompute more");
            }
            if (termsDir != null) {
                requireTermsMatchPatch(terms, field);
            }
        }
        TaylorEvaluation evaluation = terms == null ? null : TaylorEvaluation.choose(settings.expansion(), field, terms,
                highestOrder, lambdaNm != null ? Math.min(lambdaNm, lambdaMinNm) : lambdaMinNm,
                (patch, centres) -> TaylorTermComputer.computeCentred(patch, centres, reporter), reporter);
        DiffractionBrdf brdf = gpu ? null
                : evaluation == null ? DiffractionBrdf.create(settings, field, null) : evaluation.brdf(settings, field);
        Direction wi = Direction.fromSphericalDeg(thetaIDeg, phiIDeg);
        CoherenceWindow window = settings.coherenceWindow();
        reporter.info(String.format(Locale.ROOT, "%s, %dx%d patch of %.3f x %.3f um, sigma_f = %.3f x %.3f texels",
                settings.variant().cliName(), field.cols(), field.rows(), field.widthUm(), field.heightExtentUm(),
                window.sigmaTexels(field.widthUm()), window.sigmaTexels(field.heightExtentUm())));
        float[] rho = null;
        float[] xyz = null;
        if (gpu) {
            try (GpuBrdfMap map = GpuBrdfMap.of(evaluation, settings, precision, reporter)) {
                reporter.info("GPU: " + map.info().renderer() + ", " + map.info().version());
                // the bake's own note says what it baked and how long it took
                if (lambdaNm != null) {
                    rho = map.monochromatic(wi, lambdaNm, size);
                } else {
                    xyz = map.xyz(wi, size);
                }
                if (time) {
                    double ms = lambdaNm != null ? map.medianMsPerFrameMonochromatic(wi, lambdaNm, size, 2, 10)
                            : map.medianMsPerFrame(wi, size, 2, 10);
                    System.out.printf(Locale.ROOT, "gpu %.1f ms/frame (%s, %dx%d, median of 10, %s, %s)%n", ms,
                            settings.variant().cliName(), size, size, textureFormat.toLowerCase(Locale.ROOT),
                            map.info().renderer());
                }
            }
        } else if (lambdaNm != null) {
            rho = BrdfMap.monochromatic(brdf, wi, lambdaNm, size, reporter);
        } else {
            xyz = BrdfMap.xyz(brdf, wi, size, reporter);
        }
        if (lambdaNm != null) {
            double exposure = exposure(rho, wi, reporter);
            warnIfDark(rho, wi, exposure, settings, field, reporter);
            float[] grey = new float[rho.length];
            for (int i = 0; i < rho.length; i++) {
                grey[i] = (float) Srgb.encode(rho[i] * exposure);
            }
            ImageFiles.writePng(output, grey, size, size, 1);
            if (pfm != null) {
                ImageFiles.writePfm(pfm, rho, size, size, 1);
            }
        } else {
            float[] luminance = new float[size * size];
            for (int p = 0; p < luminance.length; p++) {
                luminance[p] = xyz[3 * p + 1];
            }
            double exposure = exposure(luminance, wi, reporter);
            warnIfDark(luminance, wi, exposure, settings, field, reporter);
            float[] display = new float[xyz.length];
            float[] linear = new float[xyz.length];
            for (int p = 0; p < xyz.length; p += 3) {
                Xyz c = new Xyz(xyz[p], xyz[p + 1], xyz[p + 2]);
                float[] rgb = colourPath.displayRgb(c.scaled(exposure));
                System.arraycopy(rgb, 0, display, p, 3);
                double[] lin = Srgb.linearFromXyz(c);
                for (int k = 0; k < 3; k++) {
                    linear[p + k] = (float) lin[k];
                }
            }
            ImageFiles.writePng(output, display, size, size, 3);
            if (pfm != null) {
                ImageFiles.writePfm(pfm, linear, size, size, 3);
            }
        }
        System.out.printf(Locale.ROOT, "wrote %s (%dx%d, %s%s%s) in %.1f s%n", output, size, size, settings.variant().cliName(),
                gpu ? ", gpu" : "",
                lambdaNm != null ? ", " + lambdaNm + " nm" : "", (System.nanoTime() - start) * 1e-9);
        return 0;
    }

    /** Terms from another patch would render a different surface than the one named: refuse them. */
    private void requireTermsMatchPatch(TaylorTerms terms, HeightField field) {
        boolean sameGrid = terms.rows() == field.rows() && terms.cols() == field.cols();
        boolean samePixels = Math.abs(terms.pixelSizeXUm() / field.pixelSizeXUm() - 1) < 1e-4
                && Math.abs(terms.pixelSizeYUm() / field.pixelSizeYUm() - 1) < 1e-4;
        if (!sameGrid || !samePixels) {
            throw new UserInputException(String.format(Locale.ROOT,
                    "%s was made from a %dx%d patch of %.4g x %.4g um pixels, but --patch %s is %dx%d of %.4g x %.4g um;"
                            + " precompute the terms of this patch", termsDir, terms.cols(), terms.rows(),
                    terms.pixelSizeXUm(), terms.pixelSizeYUm(), input.patch, field.cols(), field.rows(),
                    field.pixelSizeXUm(), field.pixelSizeYUm()));
        }
    }

    /** The fixed exposure, or null for auto; checked before any work is done. */
    private Double fixedExposure() {
        if (exposureText.equalsIgnoreCase("auto")) {
            return null;
        }
        try {
            double e = Double.parseDouble(exposureText);
            if (e > 0 && Double.isFinite(e)) {
                return e;
            }
        } catch (NumberFormatException ignored) {
            // falls through to the message below
        }
        throw new UserInputException("--exposure must be a positive number or auto, got '" + exposureText + "'");
    }

    private double exposure(float[] luminance, Direction wi, Reporter reporter) {
        Double fixed = fixedExposure();
        if (fixed != null) {
            return fixed;
        }
        double e = AutoExposure.of(luminance, size, -wi.x(), -wi.y());
        reporter.info(String.format(Locale.ROOT, "auto exposure %.4g", e));
        return e;
    }

    /** A black (or nearly black) picture says so, and which option shows it. */
    private void warnIfDark(float[] luminance, Direction wi, double exposure, BrdfSettings settings,
                            HeightField field, Reporter reporter) {
        double brightest = 0;
        for (float value : luminance) {
            brightest = Math.max(brightest, value);
        }
        DarkMapNotice.check(brightest, AutoExposure.brightestDiffracted(luminance, size, -wi.x(), -wi.y()), exposure,
                fixedExposure() == null, settings, field.widthUm(), field.heightExtentUm(), size)
                .ifPresent(n -> {
                    if (n.warning()) {
                        reporter.warn(n.text());
                    } else {
                        reporter.info(n.text());
                    }
                });
    }

    private static int parseWindowRadius(String text) {
        try {
            return Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw new UserInputException("--window-radius must be a whole number or auto, got '" + text + "'");
        }
    }

    /** "UV,W": the baked table's samples (0 = automatic). */
    private static int[] parseBakedSamples(String text) {
        String[] parts = text.split(",");
        try {
            if (parts.length == 2) {
                return new int[] {Integer.parseInt(parts[0].trim()), Integer.parseInt(parts[1].trim())};
            }
        } catch (NumberFormatException ignored) {
            // falls through to the message below
        }
        throw new UserInputException("--baked-samples must be UV,W (whole numbers, 0 = automatic), got '" + text + "'");
    }

    private static boolean parseEngine(String text) {
        switch (text.toLowerCase(Locale.ROOT)) {
            case "cpu":
                return false;
            case "gpu":
                return true;
            default:
                throw new UserInputException("unknown --engine '" + text + "': use cpu or gpu");
        }
    }

    private static ColourPath parseColour(String text) {
        switch (text.toLowerCase(Locale.ROOT)) {
            case "srgb":
                return ColourPath.SRGB;
            case "thesis":
                return ColourPath.THESIS;
            default:
                throw new UserInputException("unknown --colour '" + text + "': use srgb or thesis");
        }
    }
}
