package diffract.pipeline;

import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;

/**
 * Where the Taylor terms 0..N of a patch come from: the user cache on disk (computed on first use), a folder the
 * user names, or a direct computation in tests. May take seconds; reports progress through {@code reporter}.
 */
@FunctionalInterface
public interface TermSource {
    TaylorTerms terms(int highestOrder, Reporter reporter);
}
