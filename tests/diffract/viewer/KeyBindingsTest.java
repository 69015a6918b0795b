package diffract.viewer;

import com.jogamp.newt.event.KeyEvent;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** One table of controls: the docs show it as it is, and no key triggers two actions. */
class KeyBindingsTest {
    @Test
    void theDocsShowTheTable() throws IOException {
        String doc = Files.readString(Path.of("docs", "guide", "viewer.md"), StandardCharsets.UTF_8);
        assertTrue(doc.contains(KeyBindings.markdownTable()), "docs/guide/viewer.md's controls differ from KeyBindings:\n"
                + KeyBindings.markdownTable());
    }

    @Test
    void everyKeyHasOneActionAndTheHelpListsEveryRow() {
        Set<String> keys = new HashSet<>();
        for (KeyBindings.Binding binding : KeyBindings.ALL) {
            assertTrue(KeyBindings.helpText().contains(binding.input()), binding.input());
            for (KeyBindings.Trigger t : binding.triggers()) {
                assertTrue(keys.add(t.keyCode() + "/" + t.character()), "bound twice: " + t);
            }
        }
        assertNotNull(KeyBindings.actionFor(KeyEvent.VK_F1, '\0'));
        assertNotNull(KeyBindings.actionFor((short) 0, 'P'), "letters in either case");
        assertNull(KeyBindings.actionFor((short) 0, 'x'));
        assertEquals(KeyBindings.ALL.size(), KeyBindings.helpText().lines().count() - 1);
    }
}
