package diffract.app;

import diffract.app.options.ProceduralOptions;
import diffract.jrtr.contexts.HeadlessGL;
import diffract.jrtr.gl.GpuTimer;
import diffract.optics.illumination.LightSource;
import diffract.scene.LightDirection;
import diffract.util.DiskCache;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.Enumeration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Properties;
import java.util.ResourceBundle;

/**
 * The help text of every command, option and parameter: the catalogue {@code help.properties} beside this class, read
 * by picocli as the resource bundle of {@link Main} and so of every command under it. An option's text stands under
 * its longest name without dashes ({@code lambda-min}) and means the same on every command that takes the option; a
 * command whose option means something else has its own entry under the qualified key
 * ({@code diffract.precompute.lambda-min}), which picocli tries first. A command's own text is
 * {@code diffract.NAME.usage.description}; a positional parameter's stands under its {@code descriptionKey}.
 *
 * <p>Limits the code holds are not copied into the catalogue: a text names them as {@code ${bundle:value.NAME}}, and
 * this bundle answers {@code value.NAME} from the constant itself.
 */
public final class HelpText extends ResourceBundle {
    /** The catalogue, a resource beside this class. */
    static final String CATALOGUE = "help.properties";

    /** The values the texts name as {@code ${bundle:value.NAME}}, from the constants that hold them. */
    static final Map<String, String> VALUES = Map.of(
            "value.max-theta-deg", LightDirection.MAX_THETA_DEG_TEXT,
            "value.max-light-diameter-deg", Integer.toString((int) LightSource.MAX_DIAMETER_DEG),
            "value.min-frames", Integer.toString(GpuTimer.MIN_FRAMES),
            "value.cache-variable", DiskCache.ROOT_VARIABLE,
            "value.gpu-variable", HeadlessGL.GPU_VARIABLE,
            "value.max-size-px", Integer.toString(ProceduralOptions.MAX_SIZE_PX),
            "value.harmonics-margin", Integer.toString(diffract.optics.rigorous.Resolution.AUTO_MARGIN),
            "value.rigorous-layers", Integer.toString(diffract.optics.rigorous.Resolution.DEFAULT.layers()));

    private final Map<String, String> entries = new LinkedHashMap<>();

    /** Public and without arguments: {@link ResourceBundle#getBundle} makes it by its class name. */
    public HelpText() {
        entries.putAll(catalogue());
        entries.putAll(VALUES);
    }

    /** The catalogue's entries, without the values. */
    static Map<String, String> catalogue() {
        Properties p = new Properties();
        try (InputStream in = HelpText.class.getResourceAsStream(CATALOGUE)) {
            if (in == null) {
                throw new IllegalStateException(CATALOGUE + " is missing beside " + HelpText.class.getName());
            }
            p.load(new InputStreamReader(in, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        Map<String, String> m = new LinkedHashMap<>();
        p.stringPropertyNames().stream().sorted().forEach(k -> m.put(k, p.getProperty(k)));
        return m;
    }

    @Override
    protected Object handleGetObject(String key) {
        return entries.get(key);
    }

    @Override
    public Enumeration<String> getKeys() {
        return Collections.enumeration(entries.keySet());
    }
}
