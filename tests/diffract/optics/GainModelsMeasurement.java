package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.ProceduralPatches;
import diffract.optics.rigorous.ComplexIndex;
import diffract.optics.rigorous.OrderEfficiencies;
import diffract.optics.rigorous.Profile;
import diffract.optics.rigorous.Resolution;
import diffract.optics.rigorous.RigorousSolver;
import diffract.optics.settings.GainModel;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The cheap corrections of the scalar model's gain against Maxwell's equations, a measurement run on request
 * (docs/measurements/rigorous.sh, {@code -Ddiffract.measure=rigorous}): for keratin gratings of the validity map's shapes and the
 * snakes' ridges, lit at 0, 30 and 60 degrees, at 450, 550 and 650 nm, each order that carries at least 5 % of the
 * diffracted power, the scalar efficiency R_0 C |T_m|^2 / cos theta_i with each candidate factor C against the
 * rigorous efficiency; the worst and the median relative error per relief. The candidates: Stam's factor with
 * Schlick's reflectance at the half vector and his shadowing ({@link GainModel#STAM}), the same with Fresnel's exact
 * unpolarised reflectance there, the same without shadowing, Rayleigh-Rice's polarisation factor
 * ({@link GainModel#RAYLEIGH_RICE}) and Rayleigh-Rice's with Stam's shadowing. |T_m|^2 is the m-th Fourier coefficient
 * of exp(i k w h) over the profile, summed on 4096 points (the scalar model's own, free of any patch's sampling).
 * No assertion.
 */
class GainModelsMeasurement {
    static final String[] CANDIDATES = {"Stam (Schlick, shadowing)", "Stam, Fresnel's reflectance",
        "Stam, Fresnel's, no shadowing", "Rayleigh-Rice", "Rayleigh-Rice, shadowing"};

    @Test
    void theCheapGainsAgainstTheRigorousOrders() {
        Assumptions.assumeTrue("rigorous".equals(System.getProperty("diffract.measure")), "measurement on request");
        List<Profile> profiles = List.of(Profile.sinusoid(0.65, 0.1), Profile.sinusoid(1.0, 0.1),
                Profile.sinusoid(2.5, 0.1), Profile.sinusoid(2.5, 0.025), Profile.sinusoid(0.8, 0.03),
                Profile.sinusoid(1.0, 0.3), Profile.sinusoid(1.5, 0.3), Profile.triangle(2.5, 0.1, 0.8),
                ridge(ProceduralPatches.Kind.ELAPHE_RIDGE, 1.144, 0.3),
                ridge(ProceduralPatches.Kind.XENOPELTIS_RIDGE, 0.65, 0.1));
        double n = GainFactor.KERATIN_REFRACTIVE_INDEX;
        double r0 = GainFactor.normalReflectance(n);
        for (Profile p : profiles) {
            List<List<Double>> errors = new ArrayList<>();
            for (int k = 0; k < CANDIDATES.length; k++) {
                errors.add(new ArrayList<>());
            }
            for (double thetaDeg : new double[] {0, 30, 60}) {
                for (double lambdaUm : new double[] {0.45, 0.55, 0.65}) {
                    double sinI = Math.sin(Math.toRadians(thetaDeg));
                    OrderEfficiencies e = RigorousSolver.solve(p, ComplexIndex.KERATIN, lambdaUm, sinI, 0,
                            Resolution.DEFAULT);
                    double diffracted = e.totalReflected() - e.reflected(0);
                    Direction wi = new Direction(-sinI, 0, Math.cos(Math.toRadians(thetaDeg)));
                    for (int i = 0; i < e.count(); i++) {
                        int m = e.order(i);
                        double eta = e.reflected(m);
                        double am = e.alpha()[i];
                        // evanescent orders carry nothing: where only the mirror propagates, nothing is compared
                        if (m == 0 || Math.abs(am) >= 1 || !(eta > 0) || eta < 0.05 * diffracted) {
                            continue;
                        }
                        Direction wr = new Direction(am, 0, Math.sqrt(1 - am * am));
                        double t2 = coefficientPower(p, -2 * Math.PI / lambdaUm * (wi.z() + wr.z()), m);
                        double[] c = candidates(wi, wr, n);
                        for (int k = 0; k < c.length; k++) {
                            errors.get(k).add((r0 / wi.z() * c[k] * t2 - eta) / eta);
                        }
                    }
                }
            }
            StringBuilder line = new StringBuilder(p.description() + ":");
            for (int k = 0; k < CANDIDATES.length; k++) {
                double[] abs = errors.get(k).stream().mapToDouble(Math::abs).sorted().toArray();
                double worst = errors.get(k).stream().max((a, b) -> Double.compare(Math.abs(a), Math.abs(b)))
                        .orElse(Double.NaN);
                line.append(String.format(Locale.ROOT, " %s: worst %+.0f %%, median %.0f %%;", CANDIDATES[k],
                        100 * worst, abs.length > 0 ? 100 * abs[abs.length / 2] : Double.NaN));
            }
            TestReport.line(GainModelsMeasurement.class, line + " (" + errors.get(0).size() + " orders)");
        }
    }

    /** The candidates' C for light towards omega_i scattered to omega_r. */
    static double[] candidates(Direction wi, Direction wr, double n) {
        double r0 = GainFactor.normalReflectance(n);
        double cosHalf = GainFactor.cosHalfToView(wi, wr);
        double stamGeometry = GainFactor.gain(wi, wr, n, GainModel.STAM) / (GainFactor.schlickFresnel(cosHalf, r0)
                / r0);
        double shadowing = GainFactor.shadowing(wi, wr);
        double fresnel = fresnel(cosHalf, n) / r0;
        double rr = GainFactor.rayleighRice(wi, wr, n);
        return new double[] {GainFactor.gain(wi, wr, n, GainModel.STAM) * shadowing, fresnel * stamGeometry * shadowing,
            fresnel * stamGeometry, rr, rr * shadowing};
    }

    /** Fresnel's unpolarised reflectance at incidence cos theta. */
    static double fresnel(double cos, double n) {
        double c = Math.max(0, Math.min(1, cos));
        double t = Math.sqrt(n * n - (1 - c * c));
        double rs = (c - t) / (c + t);
        double rp = (n * n * c - t) / (n * n * c + t);
        return 0.5 * (rs * rs + rp * rp);
    }

    /** |T_m|^2: the m-th Fourier coefficient of exp(i a h(t)) over one period, on 4096 points. */
    static double coefficientPower(Profile p, double a, int m) {
        int k = 4096;
        double re = 0;
        double im = 0;
        for (int i = 0; i < k; i++) {
            double t = (i + 0.5) / k;
            double phase = a * p.at(t) - 2 * Math.PI * m * t;
            re += Math.cos(phase);
            im += Math.sin(phase);
        }
        re /= k;
        im /= k;
        return re * re + im * im;
    }

    private static Profile ridge(ProceduralPatches.Kind kind, double periodUm, double depthUm) {
        HeightField field = new ProceduralPatches.Spec(kind, periodUm, depthUm, 1, 64, 1, 128, 0, 1L).build()
                .meanSubtracted();
        Profile sampled = RigorousPatch.of(field).profile();
        return new Profile(sampled.periodUm(), sampled.depthUm(), sampled.heightUm(), kind.name().toLowerCase(Locale.ROOT)
                .replace('_', '-') + String.format(Locale.ROOT, " %.3g / %.3g um", periodUm, depthUm));
    }
}
