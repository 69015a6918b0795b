package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.scene.DisplayMode;

import java.util.Locale;

/**
 * The window title: what is drawn (patch, variant and its parameters, light, mode), where the refinement stands
 * (preview, refining 1/4 37%, refined), how long a full frame takes, and what is under way in the background.
 * NEWT windows have no overlay of their own, and the title stays readable whatever the picture shows.
 */
public final class ViewerTitle {
    private ViewerTitle() {
    }

    public static String of(ViewerModel model, ViewerState state, FrameStats stats, RefinementStatus refinement,
                            long nowNanos) {
        BrdfSettings drawn = state.drawableSettings();
        StringBuilder title = new StringBuilder(String.format(Locale.ROOT,
                "diffract %s | %s N=%d dlambda=%s nm R=%d | theta_i %.0f phi_i %.0f | %s%s | exposure %s",
                model.patchName(), drawn.variant().spec(), drawn.taylor().highestOrder(),
                number(drawn.spectral().lambdaStepNm()), drawn.window().radius(), state.view().light().thetaDeg(), state.view().light().phiDeg(),
                state.view().mode() == DisplayMode.BRDF_MAP ? "BRDF map" : model.shape().name(),
                state.view().pigmentationOn() && state.view().mode() == DisplayMode.SURFACE ? " + pigment" : "",
                number(state.view().exposure())));
        title.append(" | ").append(stage(refinement));
        double ms = stats.msPerFrame();
        title.append(Double.isNaN(ms) ? " | - ms/frame" : String.format(Locale.ROOT, " | %.0f ms/frame", ms));
        if (state.bake() != null) {
            title.append(String.format(Locale.ROOT, " | baking table %d%%", state.bake().percent()));
        }
        PrecomputeProgress precompute = state.precompute();
        if (precompute != null) {
            title.append(String.format(Locale.ROOT, " | precomputing N=%d %d%%", precompute.targetOrder(),
                    precompute.percent()));
        } else if (state.needsMoreTerms()) {
            title.append(" | N=").append(state.settings().taylor().highestOrder()).append(" waiting for terms");
        }
        Notice notice = state.notice();
        if (notice != null && notice.isShowingAt(nowNanos)) {
            title.append(" | ").append(notice.text());
        }
        return title.toString();
    }

    /** What the window is drawing: "preview 1/8", "refining 1/4 37%", "refined", ... */
    static String stage(RefinementStatus r) {
        return switch (r.stage()) {
            case STARTING -> "starting";
            case PREVIEW -> "preview 1/" + r.divisor();
            case REFINING -> String.format(Locale.ROOT, "refining %s %d%%", r.divisor() == 1 ? "full size"
                    : "1/" + r.divisor(), (int) Math.floor(100 * r.fraction()));
            case WAITING_FOR_TABLE -> "preview until the table is baked";
            case REFINED -> "refined";
            case FAILED -> "drawing failed";
        };
    }

    /** 5 for 5.0, 2.5 for 2.5: no trailing zeros. */
    static String number(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e9 ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%.3g", value);
    }
}
