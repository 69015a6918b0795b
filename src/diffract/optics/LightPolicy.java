package diffract.optics;

import diffract.optics.illumination.DiscFootprint;
import diffract.optics.illumination.LightSource;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.LightProfile;
import diffract.optics.settings.Quantity;

import java.util.Optional;

/**
 * Whether a method can take the light its settings name: the one answer that every command, the scene loader, the
 * viewer and the bench ask for. A point light suits every method. A light of finite size needs a method that averages
 * the BRDF over the light's directions ({@link Variant#filtersLight}: the lobes method and its baked table) or the
 * reference, which integrates it exactly; FLSS, NMM and PQ sample the light at its centre (the thesis' model). A
 * {@link LightProfile#DISC} light is taken by the same three: the reference integrates it, the lobes method averages
 * each lobe over it ({@link DiscFootprint}), the baked table's lookup integrates it over a table of the point light.
 *
 * <p>Where the user named both the method and the light (brdfmap, the library), such a pair is refused with
 * {@link #reason}; where the light comes from a scene (scene files, the viewer's keys), it is drawn as a point light
 * ({@link #usable}) with {@link #notice} said once.
 *
 * @param asked  the settings as given
 * @param usable the settings the method can draw: {@code asked}, or {@code asked} under a point light
 * @param reason why the method cannot take the light, and what can; empty when it can
 */
public record LightPolicy(BrdfSettings asked, BrdfSettings usable, Optional<String> reason) {
    /** The decision for {@code settings}. */
    public static LightPolicy of(BrdfSettings settings) {
        Variant v = settings.variant();
        LightSource light = settings.illumination().light();
        if (light.isPoint() || v.filtersLight()) {
            return new LightPolicy(settings, settings, Optional.empty());
        }
        return new LightPolicy(settings, settings.with(b -> b.lightSizeDeg(0)), Optional.of(v.label()
                + " samples the light at its centre only: a light of "
                + InvalidSettingException.number(light.angularDiameterDeg()) + " degrees ("
                + light.profile().label() + ") needs a method that averages over it, " + Methods.listed(
                Variant::filtersLight, "or") + " (or a point light, 0 degrees)"));
    }

    /** The quantity a refusal is about: the light's size. */
    public Quantity quantity() {
        return Quantity.LIGHT_SIZE;
    }

    /** Whether the method takes the light as asked. */
    public boolean accepted() {
        return reason.isEmpty();
    }

    /** The settings as asked, or the refusal (one line naming the light's size) where the method cannot take them. */
    public BrdfSettings requireAccepted() {
        if (reason.isPresent()) {
            throw new InvalidSettingException(quantity(), reason.get());
        }
        return asked;
    }

    /** What a scene or the viewer says when it draws {@link #usable} instead of what was asked; empty if nothing. */
    public Optional<String> notice() {
        return reason.map(r -> asked.variant().spec() + " samples the light at its centre: the "
                + InvalidSettingException.number(asked.illumination().light().angularDiameterDeg())
                + "-degree light is drawn as a point light (" + Methods.listed(v -> v.filtersLight() && v.runsOnGpu(),
                "and") + " filter by its size)");
    }
}
