package diffract.viewer;

import diffract.optics.TaylorTerms;
import diffract.util.Reporter;

/**
 * Where the viewer gets Taylor terms 0..N of its patch: the user cache on disk for the CLI
 * ({@code Precomputation.cached}), a direct computation in tests. Called on a background thread; may take seconds
 * and reports progress through {@code reporter}.
 */
@FunctionalInterface
public interface TermSource {
    TaylorTerms terms(int highestOrder, Reporter reporter);
}
