package diffract.viewer;

import java.util.List;

/** The controls, in one place for the help text, the docs and the tests. */
public final class KeyBindings {
    /** One control and what it does. */
    public record Binding(String input, String action) {
    }

    public static final List<Binding> ALL = List.of(
            new Binding("left drag", "orbit the camera (the shading follows it)"),
            new Binding("wheel", "zoom"),
            new Binding("right drag", "move the light (theta_i up/down, phi_i left/right)"),
            new Binding("1 / 2 / 3", "variant FLSS / NMM / PQ"),
            new Binding("+ / -", "Taylor terms N up / down (more terms are precomputed in the background)"),
            new Binding("[ / ]", "lambda step down / up (1, 2, 5, 10, 20, 40 nm)"),
            new Binding("up / down", "theta_i -5 / +5 degrees"),
            new Binding("left / right", "phi_i -15 / +15 degrees"),
            new Binding("PgUp / PgDn", "exposure x1.5 / /1.5"),
            new Binding("B", "BRDF-map mode on / off"),
            new Binding("P", "pigmentation on / off (needs --pigmentation FILE)"),
            new Binding("S", "screenshot of the window (PNG; the path is printed)"),
            new Binding("R", "reset camera, light and settings"),
            new Binding("H / F1", "this help"),
            new Binding("Esc / Q", "quit"));

    private KeyBindings() {
    }

    /** The help text printed to standard output. */
    public static String helpText() {
        StringBuilder text = new StringBuilder("diffract viewer controls:\n");
        for (Binding binding : ALL) {
            text.append(String.format("  %-13s %s%n", binding.input(), binding.action()));
        }
        return text.toString();
    }

    /** The help squeezed into a title line. */
    public static String oneLine() {
        return "drag orbit, wheel zoom, right-drag light, 1/2/3 variant, +/- N, [/] lambda step, arrows light, "
                + "PgUp/PgDn exposure, B map, P pigment, S screenshot, R reset, Q quit";
    }
}
