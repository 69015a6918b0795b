package diffract.bench;

import diffract.optics.BrdfSettings;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.TaylorExpansion;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Which configurations the bench measures, table-driven: every GPU {@link Variant} (all but the CPU-only
 * reference) is swept over the same points, and {@link Variant#unsweptSettings} says which axes a variant
 * ignores (their value stays the thesis' and duplicates are dropped). A new variant needs no line here at all.
 */
public final class SweepPlan {
    /** The axes of a configuration. */
    public enum Axis {
        TERMS(Quantity.HIGHEST_ORDER), LAMBDA_STEP(Quantity.LAMBDA_STEP), WINDOW_RADIUS(Quantity.WINDOW_RADIUS),
        TEXTURE_FORMAT(Quantity.TERM_FORMAT), SIZE(null), LEAN(Quantity.TAYLOR_TOLERANCE);

        /** The setting it sweeps (none for the map's size). */
        private final Quantity quantity;

        Axis(Quantity quantity) {
            this.quantity = quantity;
        }

        /** Whether a sweep holds it at the thesis' value for {@code method} ({@link Variant#unsweptSettings}). */
        boolean heldFor(Variant method) {
            return quantity != null && method.unsweptSettings().contains(quantity);
        }
    }

    /**
     * The Taylor tolerance of the "lean" points: each lookup's loop stops at its own Lagrange bound (docs/measurements/baked.md
     * measures 1e-4 as invisible in CIEDE2000 at 17-40 % less work), with the automatic window.
     */
    public static final double LEAN_TAYLOR_TOLERANCE = 1e-4;

    /** The thesis' storage: float32 terms. */
    public static final TermFormat EXACT_FORMAT = TermFormat.RG32F;

    /**
     * One point of the sweep.
     *
     * @param terms the highest Taylor order N (the thesis' "30 terms" is N = 30, as {@code --terms})
     * @param lean  each lookup's Taylor loop stops at {@link #LEAN_TAYLOR_TOLERANCE} and the window radius follows
     *              sigma_f ({@code windowRadius} then does not apply)
     */
    public record Point(int terms, double lambdaStepNm, int windowRadius, TermFormat textureFormat, int sizePx,
                        boolean lean) {
        public Point(int terms, double lambdaStepNm, int windowRadius, TermFormat textureFormat, int sizePx) {
            this(terms, lambdaStepNm, windowRadius, textureFormat, sizePx, false);
        }

        Point with(int n, double step, int r) {
            return new Point(n, step, r, textureFormat, sizePx, lean);
        }

        Point format(TermFormat f) {
            return new Point(terms, lambdaStepNm, windowRadius, f, sizePx, lean);
        }

        Point size(int s) {
            return new Point(terms, lambdaStepNm, windowRadius, textureFormat, s, lean);
        }

        /** The same point modelling only what the patch requires: early stop and automatic window. */
        Point asLean() {
            return new Point(terms, lambdaStepNm, windowRadius, textureFormat, sizePx, true);
        }
    }

    private SweepPlan() {
    }

    /** The variants the full sweep measures, in enum order. */
    public static List<Variant> sweptVariants() {
        return sweptVariants(false);
    }

    /**
     * The variants a sweep measures, in the registry's order. {@code quick} leaves out those that draw a table (and so
     * left out of auto's calibration): a table first bakes, 30 to 70 s per patch on llvmpipe (docs/measurements/baked.md), which
     * alone would exceed the quick sweep's budget of a few minutes.
     */
    public static List<Variant> sweptVariants(boolean quick) {
        List<Variant> variants = new ArrayList<>();
        for (Variant v : Variant.values()) {
            if (v.runsOnGpu() && !(quick && v.drawsTable())) {
                variants.add(v);
            }
        }
        return variants;
    }

    /** The thesis' point: 30 terms, 5 nm, a 3 x 3 window, float32 terms (001 implementation notes). */
    public static Point thesis(int sizePx) {
        return new Point(30, 5, 1, EXACT_FORMAT, sizePx);
    }

    /**
     * {@code --quick}: the thesis' point, each axis alone one to three steps cheaper, both cheaper term formats,
     * cheap corners where several savings combine (where an accuracy target's cheapest choice usually lies), and
     * the lean version (early stop, automatic window) of the thesis' point and of two corners.
     */
    public static List<Point> quick(int sizePx) {
        Point t = thesis(sizePx);
        return List.of(t,
                t.with(16, 5, 1), t.with(8, 5, 1), t.with(4, 5, 1), t.with(30, 10, 1), t.with(30, 25, 1),
                t.with(30, 5, 0), t.format(TermFormat.RG16F), t.format(TermFormat.RG8),
                t.with(8, 10, 1), t.with(4, 10, 1), t.with(8, 25, 1), t.with(8, 10, 0), t.with(8, 10, 1).format(TermFormat.RG8),
                t.asLean(), t.with(8, 10, 1).asLean(), t.with(4, 10, 1).asLean());
    }

    /**
     * The full sweep: N x step x R over {4, 6, 8, 16, 30} x {5, 10, 15, 25} x {0, 1} with float32 terms; at the
     * thesis' point the 1 nm step, a 5 x 5 window and N = 40; the three term formats at three points; and the
     * thesis' point at {@code largeSizePx}; and the lean version (early stop, automatic window) of five points.
     */
    public static List<Point> full(int sizePx, int largeSizePx) {
        Point t = thesis(sizePx);
        List<Point> points = new ArrayList<>(grid(List.of(4, 6, 8, 16, 30), List.of(5.0, 10.0, 15.0, 25.0), List.of(0, 1),
                List.of(EXACT_FORMAT), List.of(sizePx)));
        points.add(t.with(30, 1, 1));
        points.add(t.with(30, 5, 2));
        points.add(t.with(40, 5, 1));
        for (Point p : List.of(t, t.with(8, 10, 1), t.with(8, 10, 0))) {
            points.add(p.format(TermFormat.RG16F));
            points.add(p.format(TermFormat.RG8));
        }
        points.add(t.size(largeSizePx));
        for (Point p : List.of(t, t.with(16, 5, 1), t.with(8, 10, 1), t.with(4, 10, 1), t.with(8, 15, 1))) {
            points.add(p.asLean());
        }
        return points;
    }

    /** Every combination of the given values. */
    public static List<Point> grid(List<Integer> terms, List<Double> stepsNm, List<Integer> radii,
                                   List<TermFormat> formats, List<Integer> sizes) {
        List<Point> points = new ArrayList<>();
        for (int size : sizes) {
            for (TermFormat f : formats) {
                for (int n : terms) {
                    for (double step : stepsNm) {
                        for (int r : radii) {
                            points.add(new Point(n, step, r, f, size));
                        }
                    }
                }
            }
        }
        return points;
    }

    /** The Taylor expansion a swept variant sums ({@link Variant#sweptExpansion}). */
    static TaylorExpansion expansionOf(Variant v) {
        return v.sweptExpansion();
    }

    /**
     * The configurations: every patch x variant x point, with the axes a variant ignores reset to the thesis'
     * value and duplicates dropped (first occurrence kept, order preserved).
     *
     * @param base the settings that are not swept (wavelength range, coherence, refractive index)
     */
    public static List<BenchConfig> configs(List<String> patches, List<Variant> variants, List<Point> points,
                                            BrdfSettings base) {
        Map<String, BenchConfig> unique = new LinkedHashMap<>();
        for (String patch : patches) {
            for (Variant v : variants) {
                Set<Axis> ignored = EnumSet.noneOf(Axis.class);
                for (Axis axis : Axis.values()) {
                    if (axis.heldFor(v)) {
                        ignored.add(axis);
                    }
                }
                Point thesis = thesis(0);
                for (Point p : points) {
                    boolean lean = p.lean() && !ignored.contains(Axis.LEAN);
                    BrdfSettings s = base.toBuilder().variant(v)
                            .highestOrder(ignored.contains(Axis.TERMS) ? thesis.terms() : p.terms())
                            .lambdaStepNm(ignored.contains(Axis.LAMBDA_STEP) ? thesis.lambdaStepNm() : p.lambdaStepNm())
                            .windowRadius(ignored.contains(Axis.WINDOW_RADIUS) ? thesis.windowRadius() : p.windowRadius())
                            .taylorTolerance(lean ? LEAN_TAYLOR_TOLERANCE : 0).automaticWindowRadius(lean)
                            .termFormat(ignored.contains(Axis.TEXTURE_FORMAT) ? EXACT_FORMAT : p.textureFormat())
                            .expansion(expansionOf(v))
                            .build();
                    BenchConfig c = new BenchConfig(patch, s, p.sizePx());
                    unique.putIfAbsent(c.key(), c);
                }
            }
        }
        return new ArrayList<>(unique.values());
    }
}
