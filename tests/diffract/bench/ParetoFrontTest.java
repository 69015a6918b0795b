package diffract.bench;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

class ParetoFrontTest {
    record P(String name, double ms, double error) {
    }

    private static List<String> front(P... points) {
        return ParetoFront.of(List.of(points), P::ms, P::error).stream().map(P::name).toList();
    }

    @Test
    void keepsOnlyPointsNoOtherBeatsInBothTimeAndError() {
        // b is beaten by a (cheaper and more accurate); d by c; e is the cheapest; f the most accurate
        assertEquals(List.of("e", "a", "c", "f"), front(
                new P("a", 2, 3), new P("b", 3, 4), new P("c", 5, 1), new P("d", 6, 1.5), new P("e", 1, 9),
                new P("f", 10, 0.5)));
    }

    @Test
    void ofEqualTimesOnlyTheMostAccurateAndOfEqualErrorsOnlyTheCheapest() {
        assertEquals(List.of("c", "b"), front(new P("a", 2, 3), new P("b", 2, 1), new P("c", 1, 5), new P("d", 4, 5)));
        assertEquals(List.of("x"), front(new P("x", 1, 1), new P("y", 3, 1)));
    }

    @Test
    void nanPointsAreNeverOnTheFrontAndAnEmptyInputGivesAnEmptyFront() {
        assertEquals(List.of("a"), front(new P("a", 2, 3), new P("n", 1, Double.NaN), new P("m", Double.NaN, 0)));
        assertEquals(List.of(), front());
    }

    @Test
    void theFrontIsSortedByTimeWithFallingError() {
        List<P> points = new java.util.ArrayList<>();
        java.util.Random random = new java.util.Random(5);
        for (int i = 0; i < 200; i++) {
            points.add(new P("p" + i, 1 + 100 * random.nextDouble(), 10 * random.nextDouble()));
        }
        List<P> front = ParetoFront.of(points, P::ms, P::error);
        for (int i = 1; i < front.size(); i++) {
            assertEquals(true, front.get(i).ms() > front.get(i - 1).ms() && front.get(i).error() < front.get(i - 1).error());
        }
        // and no point of the input beats a front point in both
        for (P f : front) {
            for (P p : points) {
                assertEquals(false, p.ms() <= f.ms() && p.error() <= f.error() && (p.ms() < f.ms() || p.error() < f.error()),
                        p + " beats front point " + f);
            }
        }
    }
}
