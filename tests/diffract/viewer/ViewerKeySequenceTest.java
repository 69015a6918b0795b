package diffract.viewer;

import com.jogamp.newt.event.KeyEvent;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tag;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Whatever keys a user presses, in whatever order and display mode, the viewer keeps drawing: random sequences of
 * the viewer's keys (variants, N, the wavelength step, the light, exposure, BRDF-map mode, pigment, reset) go
 * through {@link KeyBindings} and the controller into a refining renderer drawing offscreen, and after each key the
 * picture is drawn to the end without a failure. Screenshot, help and quit are left out (they draw nothing new).
 */
@Tag("gl")
class ViewerKeySequenceTest {
    /** A key as the window's listener passes it: a NEWT key code, or a character. */
    record Key(short code, char character) {
        @Override
        public String toString() {
            return code == KeyEvent.VK_UP ? "up" : code == KeyEvent.VK_DOWN ? "down" : code == KeyEvent.VK_LEFT ? "left"
                    : code == KeyEvent.VK_RIGHT ? "right" : code == KeyEvent.VK_PAGE_UP ? "PgUp"
                    : code == KeyEvent.VK_PAGE_DOWN ? "PgDn" : String.valueOf(character);
        }
    }

    static final List<Key> KEYS = List.of(new Key((short) 0, '1'), new Key((short) 0, '2'), new Key((short) 0, '3'),
            new Key((short) 0, '4'), new Key((short) 0, '+'), new Key((short) 0, '-'), new Key((short) 0, '['),
            new Key((short) 0, ']'), new Key((short) 0, 'b'), new Key((short) 0, 'p'), new Key((short) 0, 'r'),
            new Key(KeyEvent.VK_UP, '\0'), new Key(KeyEvent.VK_DOWN, '\0'), new Key(KeyEvent.VK_LEFT, '\0'),
            new Key(KeyEvent.VK_RIGHT, '\0'), new Key(KeyEvent.VK_PAGE_UP, '\0'), new Key(KeyEvent.VK_PAGE_DOWN, '\0'));
    /** Display calls allowed to finish one picture (each draws tiles for about 50 ms; a 32 x 24 picture needs few). */
    static final int MAX_DISPLAYS = 400;

    @Provide
    Arbitrary<List<Key>> sequences() {
        return Arbitraries.of(KEYS).list().ofMinSize(1).ofMaxSize(8);
    }

    @Property(tries = 8)
    void everyKeySequenceKeepsDrawing(@ForAll("sequences") List<Key> keys) throws InterruptedException {
        assertKeepsDrawing(keys);
    }

    /** The BRDF map, then the lobes method, then one more term: the lobes' uniforms on the preview's program. */
    @Example
    void theLobesMethodsMapWhileMoreTermsArePrecomputed() throws InterruptedException {
        assertKeepsDrawing(List.of(new Key((short) 0, 'b'), new Key((short) 0, '4'), new Key((short) 0, '+'),
                new Key((short) 0, '+'), new Key((short) 0, '-'), new Key((short) 0, 'b')));
    }

    private static void assertKeepsDrawing(List<Key> keys) throws InterruptedException {
        GlTestSupport.assumeOffscreenGl();
        ViewerModel model = ViewerTestSupport.model(ViewerTestSupport.directTerms());
        List<String> pressed = new ArrayList<>();
        try (TermPrecomputer precomputer = new TermPrecomputer(model);
             TableBaker baker = new TableBaker(model)) {
            ViewerController controller = new ViewerController(model, precomputer, () -> null, () -> { });
            RefiningRenderer refining = new RefiningRenderer(model, new ViewerRenderer(model), baker);
            refining.drawOn(Thread.currentThread());
            try (OffscreenTarget target = new OffscreenTarget(refining)) {
                drawToTheEnd(target, refining, model, pressed);
                for (Key key : keys) {
                    controller.handleKey(key.code(), key.character());
                    controller.applyQueuedInput(0);
                    pressed.add(key.toString());
                    drawToTheEnd(target, refining, model, pressed);
                }
            }
        }
    }

    /** Draws until the picture of the model's state is refined (terms precomputed meanwhile included). */
    private static void drawToTheEnd(OffscreenTarget target, RefiningRenderer refining, ViewerModel model,
                                     List<String> pressed) throws InterruptedException {
        for (int i = 0; i < MAX_DISPLAYS; i++) {
            target.renderRgba(32, 24);
            RefinementStatus status = refining.status();
            assertNotEquals(RefinementStatus.Stage.FAILED, status.stage(), () -> "after " + pressed + ": "
                    + model.state().notice());
            if (status.isRefined(model.state()) && model.state().precompute() == null && !refining.needsDisplay()) {
                return;
            }
            if (!refining.needsDisplay()) {
                Thread.sleep(20); // a precompute in the background: the next state comes from it
            }
        }
        assertTrue(false, "after " + pressed + " the picture was not finished in " + MAX_DISPLAYS + " displays: "
                + refining.status().stage());
    }
}
