package diffract.render;

import diffract.optics.Variant;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The GPU sides of the methods ({@link GpuMethod}), by the method's label: the built-in ones, and any a caller
 * registers beside its method ({@link diffract.optics.Methods}).
 */
public final class GpuMethods {
    private static final Map<String, GpuMethod> BY_LABEL = new ConcurrentHashMap<>(Map.of(
            Variant.FLSS.label(), new FlssGpu(),
            Variant.NMM.label(), new NmmGpu(),
            Variant.PQ.label(), new PqGpu(),
            Variant.BAKED.label(), new BakedGpu(),
            Variant.LOBES.label(), new LobesGpu()));

    private GpuMethods() {
    }

    /** The GPU side of a method that runs on the GPU. */
    public static GpuMethod of(Variant method) {
        GpuMethod gpu = BY_LABEL.get(method.label());
        if (gpu == null) {
            throw new IllegalArgumentException("the method " + method.label() + " has no GPU side");
        }
        return gpu;
    }

    /** Registers the GPU side of a method (replacing any of the same label). */
    public static void register(Variant method, GpuMethod gpu) {
        BY_LABEL.put(method.label(), gpu);
    }

    /** Removes a method's GPU side. */
    public static void unregister(Variant method) {
        BY_LABEL.remove(method.label());
    }
}
