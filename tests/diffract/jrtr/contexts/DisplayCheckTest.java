package diffract.jrtr.contexts;

import org.junit.jupiter.api.Test;

import java.util.Map;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;

class DisplayCheckTest {
    @Test
    void linuxWithoutDisplayGetsTheInstallHint() {
        assertEquals(Optional.of(DisplayCheck.NO_DISPLAY_MESSAGE), DisplayCheck.problem(Map.of(), "Linux"));
        assertEquals(Optional.of(DisplayCheck.NO_DISPLAY_MESSAGE),
                DisplayCheck.problem(Map.of("DISPLAY", " "), "Linux"));
        assertEquals("no X display: run under xvfb-run, or install xvfb (apt-get install xvfb xauth libgl1-mesa-dri)",
                DisplayCheck.NO_DISPLAY_MESSAGE);
    }

    @Test
    void displaySetOrNonX11SystemsAreFine() {
        assertEquals(Optional.empty(), DisplayCheck.problem(Map.of("DISPLAY", ":99"), "Linux"));
        assertEquals(Optional.empty(), DisplayCheck.problem(Map.of(), "Windows 11"));
        assertEquals(Optional.empty(), DisplayCheck.problem(Map.of(), "Mac OS X"));
    }

    @Test
    void requireDisplayAgreesWithProblem() {
        if (DisplayCheck.problem().isPresent()) {
            diffract.util.UserInputException e = org.junit.jupiter.api.Assertions.assertThrows(
                    diffract.util.UserInputException.class, DisplayCheck::requireDisplay);
            assertEquals(DisplayCheck.NO_DISPLAY_MESSAGE, e.getMessage());
        } else {
            org.junit.jupiter.api.Assertions.assertDoesNotThrow(DisplayCheck::requireDisplay);
        }
    }
}
