package diffract.viewer;

import com.jogamp.newt.event.KeyEvent;
import diffract.optics.Variant;

import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * The viewer's controls, the one table the controller dispatches keys from and the help (stdout, the title, the
 * docs' table) is printed from. A new control is one row here and, if it needs one, an action in
 * {@link ViewerController}.
 */
public final class KeyBindings {
    /**
     * A key that triggers an action: a NEWT key code (arrows, page keys, F1, Esc, the keypad's + and -), or a
     * character (compared in lower case). The controller queues actions for the render loop, which applies them
     * between the tiles it draws; an {@code immediate} one runs on the input thread at once (quitting must not
     * wait for a tile).
     */
    public record Trigger(short keyCode, char character, Consumer<ViewerController> action, boolean immediate) {
        static Trigger code(short keyCode, Consumer<ViewerController> action) {
            return new Trigger(keyCode, '\0', action, false);
        }

        static Trigger character(char c, Consumer<ViewerController> action) {
            return new Trigger((short) 0, c, action, false);
        }

        Trigger immediately() {
            return new Trigger(keyCode, character, action, true);
        }

        boolean matches(short code, char c) {
            return keyCode != 0 ? keyCode == code : character == Character.toLowerCase(c);
        }
    }

    /**
     * One row of the help.
     *
     * @param input    the keys or mouse input, as the help shows them
     * @param action   what it does
     * @param brief    the few words the title's one-line help gives it
     * @param triggers the keys the controller dispatches (none for the mouse, which its listener handles)
     */
    public record Binding(String input, String action, String brief, List<Trigger> triggers) {
    }

    /** The methods' own keys ({@link Variant#viewerKey}), as one row: "1 / 2 / 3 / 4", "variant flss / ... ". */
    private static Binding variantKeys() {
        List<Variant> keyed = java.util.Arrays.stream(Variant.values()).filter(v -> v.viewerKey() != 0).toList();
        List<Trigger> triggers = keyed.stream().map(v -> Trigger.character(v.viewerKey(), c -> c.selectVariant(v)))
                .toList();
        String keys = String.join(" / ", keyed.stream().map(v -> String.valueOf(v.viewerKey())).toList());
        String labels = String.join(" / ", keyed.stream().map(Variant::label).toList());
        String brief = keyed.get(0).viewerKey() + "-" + keyed.get(keyed.size() - 1).viewerKey() + " variant";
        return new Binding(keys, "variant " + labels, brief, triggers);
    }

    public static final List<Binding> ALL = List.of(
            new Binding("left drag", "orbit the camera (the shading follows it); on the A/B divider, move it", "drag orbit",
                    List.of()),
            new Binding("wheel", "zoom", "wheel zoom", List.of()),
            new Binding("right drag", "move the light (theta_i up/down, phi_i left/right)", "right-drag light", List.of()),
            variantKeys(),
            new Binding("+ / -", "Taylor terms N up / down; more terms than precomputed start a background precompute",
                    "+/- N", List.of(
                    Trigger.code(KeyEvent.VK_ADD, c -> c.changeTaylorOrderBy(1)),
                    Trigger.code(KeyEvent.VK_SUBTRACT, c -> c.changeTaylorOrderBy(-1)),
                    Trigger.character('+', c -> c.changeTaylorOrderBy(1)),
                    Trigger.character('=', c -> c.changeTaylorOrderBy(1)), // '+' without shift on US keyboards
                    Trigger.character('-', c -> c.changeTaylorOrderBy(-1)),
                    Trigger.character('_', c -> c.changeTaylorOrderBy(-1)))),
            new Binding("[ / ]", "lambda step down / up (1, 2, 5, 10, 20, 40 nm)", "[/] lambda step", List.of(
                    Trigger.character('[', c -> c.changeLambdaStep(-1)),
                    Trigger.character(']', c -> c.changeLambdaStep(1)))),
            new Binding("up / down", "theta_i -5 / +5 degrees", "arrows light", List.of(
                    Trigger.code(KeyEvent.VK_UP, c -> c.moveLightBy(-5, 0)),
                    Trigger.code(KeyEvent.VK_DOWN, c -> c.moveLightBy(5, 0)))),
            new Binding("left / right", "phi_i -15 / +15 degrees", null, List.of(
                    Trigger.code(KeyEvent.VK_LEFT, c -> c.moveLightBy(0, -15)),
                    Trigger.code(KeyEvent.VK_RIGHT, c -> c.moveLightBy(0, 15)))),
            new Binding("PgUp / PgDn", "exposure x1.5 / /1.5", "PgUp/PgDn exposure", List.of(
                    Trigger.code(KeyEvent.VK_PAGE_UP, c -> c.changeExposure(1)),
                    Trigger.code(KeyEvent.VK_PAGE_DOWN, c -> c.changeExposure(-1)))),
            new Binding("B", "BRDF-map mode on / off (the map of the current light, centred)", "B map", List.of(
                    Trigger.character('b', ViewerController::toggleBrdfMap))),
            new Binding("P", "pigmentation on / off (the scene's image, --pigmentation IMAGE, or the snake's "
                    + "procedural pattern)", "P pigment", List.of(
                    Trigger.character('p', ViewerController::togglePigmentation))),
            new Binding("S", "screenshot of the window (PNG into --screenshot-dir, default out/; the path is printed)",
                    "S screenshot", List.of(Trigger.character('s', ViewerController::screenshot))),
            new Binding("R", "reset camera, light and settings (precomputed terms are kept)", "R reset", List.of(
                    Trigger.character('r', ViewerController::reset))),
            new Binding("H / F1", "help: this list on stdout and, briefly, in the title", null, List.of(
                    Trigger.character('h', ViewerController::showHelp),
                    Trigger.code(KeyEvent.VK_F1, ViewerController::showHelp))),
            new Binding("Esc / Q", "quit", "Q quit", List.of(
                    Trigger.code(KeyEvent.VK_ESCAPE, ViewerController::quit).immediately(),
                    Trigger.character('q', ViewerController::quit).immediately())));

    private KeyBindings() {
    }

    /** The action of a key press, key codes first (the keypad's + has a character too); null when none. */
    static Consumer<ViewerController> actionFor(short keyCode, char keyChar) {
        Trigger t = triggerFor(keyCode, keyChar);
        return t == null ? null : t.action();
    }

    /** The trigger a key press matches, key codes first; null when none. */
    static Trigger triggerFor(short keyCode, char keyChar) {
        for (boolean byCode : new boolean[] {true, false}) {
            for (Binding binding : ALL) {
                for (Trigger t : binding.triggers()) {
                    if ((t.keyCode() != 0) == byCode && t.matches(keyCode, keyChar)) {
                        return t;
                    }
                }
            }
        }
        return null;
    }

    /** The help text printed to standard output. */
    public static String helpText() {
        StringBuilder text = new StringBuilder("diffract viewer controls:\n");
        for (Binding binding : ALL) {
            text.append(String.format(Locale.ROOT, "  %-13s %s%n", binding.input(), binding.action()));
        }
        return text.toString();
    }

    /** The help squeezed into a title line. */
    public static String oneLine() {
        StringBuilder line = new StringBuilder();
        for (Binding binding : ALL) {
            if (binding.brief() != null) {
                line.append(line.length() == 0 ? "" : ", ").append(binding.brief());
            }
        }
        return line.toString();
    }

    /** The table of docs/guide/viewer.md. */
    public static String markdownTable() {
        StringBuilder table = new StringBuilder("| input | action |\n|---|---|\n");
        for (Binding binding : ALL) {
            table.append("| ").append(binding.input()).append(" | ").append(binding.action()).append(" |\n");
        }
        return table.toString();
    }
}
