// Which Taylor expansion of exp(i k w h) the windowed sum uses (PhaseCentres, PhaseCentredSpectrum).
// Included by diffraction_common.glsl after taylorCoefficients().
//
// Plain (the thesis, 004 eq. finalexpression): c_n = (k w)^n / n! around 0, the terms DFT_n in layers 0..N.
// PHASE_CENTRED: around the nearest centre a_j = -j * centreSpacingPerUm, c_n = (k w - a_j)^n / n!, and the terms
// E_{j,n} = fftshift(ifft2(exp(i a_j h) (i h)^n)) in layers j * TERM_COUNT + n (TERM_COUNT = orders per centre).
// Around 0 the terms grow like e^{k|w| max|h|} before they cancel and float32 turns tall patches into noise;
// around a_j every term is at most b^n / n! (b = |k w - a_j| max|h| <= 2) and nothing cancels.
#ifndef TAYLOR_CENTRED_GLSL
#define TAYLOR_CENTRED_GLSL

#ifdef PHASE_CENTRED
// PhaseCentres.spacingPerUm and centreCount.
uniform float centreSpacingPerUm;
uniform int centreCount;

// PhaseCentres.nearestCentre: round(-a / spacing), clamped to the centres that exist (a = k w <= 0).
int nearestPhaseCentre(float kw) {
    return clamp(int(floor(-kw / centreSpacingPerUm + 0.5)), 0, centreCount - 1);
}

// The coefficients of the expansion around the nearest centre; returns the centre's first texture layer.
int taylorExpansion(float kw, out float c[TERM_COUNT]) {
    int j = nearestPhaseCentre(kw);
    taylorCoefficients(kw + float(j) * centreSpacingPerUm, c); // k w - a_j
    return j * TERM_COUNT;
}

// The phase the series expands: k w - a_j around the nearest centre.
float expansionPhase(float kw) {
    return kw + float(nearestPhaseCentre(kw)) * centreSpacingPerUm;
}
#else
// The thesis' series around 0: layers 0..N.
int taylorExpansion(float kw, out float c[TERM_COUNT]) {
    taylorCoefficients(kw, c);
    return 0;
}

// The phase the series expands: k w itself.
float expansionPhase(float kw) {
    return kw;
}
#endif

#endif
