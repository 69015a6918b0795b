package diffract.jrtr.contexts;

import diffract.util.UserInputException;
import org.lwjgl.PointerBuffer;
import org.lwjgl.egl.EGL;
import org.lwjgl.egl.EGL10;
import org.lwjgl.egl.EXTDeviceEnumeration;
import org.lwjgl.egl.EXTDeviceQuery;
import org.lwjgl.system.Configuration;
import org.lwjgl.system.JNI;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;

/**
 * An initialised EGL display for headless desktop OpenGL, on the platform and device the rules below choose.
 *
 * <ul>
 *   <li>A GPU index given ({@code --gpu N}, or the environment variable {@value HeadlessGL#GPU_VARIABLE}): EGL device
 *       N of {@code eglQueryDevicesEXT}, through {@code EGL_EXT_platform_device}. On an NVIDIA or AMD server that is
 *       how a GPU is picked without an X server.</li>
 *   <li>None given: the first device that is not Mesa's software rasteriser, then Mesa's surfaceless platform
 *       ({@code EGL_MESA_platform_surfaceless}: a render node if there is one, else llvmpipe), then the software
 *       device, then {@code EGL_DEFAULT_DISPLAY}: the first that initialises.</li>
 * </ul>
 *
 * <p>Displays live as long as the process: EGL hands out one display per platform and device, and terminating it
 * would end every other context on it.
 */
public final class EglDisplay {
    static final int EGL_PLATFORM_DEVICE_EXT = 0x313F;
    static final int EGL_PLATFORM_SURFACELESS_MESA = 0x31DD;
    private static final int EGL_DRM_DEVICE_FILE_EXT = 0x3233;
    private static final int EGL_DRM_RENDER_NODE_FILE_EXT = 0x3377;
    private static final int EGL_RENDERER_EXT = 0x335F;

    static {
        // LWJGL then looks the GL functions up with eglGetProcAddress, so no GLX library is needed
        Configuration.OPENGL_CONTEXT_API.set("EGL");
    }

    /** One EGL device as {@code eglQueryDevicesEXT} lists it. */
    record Device(int index, long handle, String description, boolean software) {
        @Override
        public String toString() {
            return index + ": " + description;
        }
    }

    final long handle;
    /** e.g. "EGL surfaceless" or "EGL device 1 of 2 (/dev/dri/renderD129)". */
    final String description;
    final Set<String> extensions;
    final int[] eglVersion;

    private EglDisplay(long handle, String description, int[] eglVersion) {
        this.handle = handle;
        this.description = description;
        this.eglVersion = eglVersion;
        String list = EGL10.eglQueryString(handle, EGL10.EGL_EXTENSIONS);
        this.extensions = Set.copyOf(Arrays.asList((list == null ? "" : list.trim()).split("\\s+")));
    }

    /**
     * Opens the display the rules choose: {@code gpuIndex} an EGL device index, or null for the automatic choice.
     * Throws {@link UserInputException} with the reason (and the devices found) when none initialises.
     */
    public static EglDisplay open(Integer gpuIndex) {
        try {
            EGL.getCapabilities(); // loads libEGL.so.1
        } catch (RuntimeException | UnsatisfiedLinkError e) {
            throw new UserInputException("no EGL library (" + e.getMessage() + "): install libegl1 libegl-mesa0 "
                    + "libgl1-mesa-dri, or a GPU driver's EGL", e);
        }
        Set<String> client = clientExtensions();
        List<Device> devices = client.contains("EGL_EXT_device_enumeration") || client.contains("EGL_EXT_device_base")
                ? devices() : List.of();
        boolean platformDevice = client.contains("EGL_EXT_platform_device");
        if (gpuIndex != null) {
            if (!platformDevice || gpuIndex < 0 || gpuIndex >= devices.size()) {
                throw new UserInputException("GPU " + gpuIndex + " not found: " + (platformDevice
                        ? devices.size() + " EGL device(s)" + (devices.isEmpty() ? "" : ": " + devices)
                        : "this EGL cannot choose devices (no EGL_EXT_platform_device)")
                        + "; give no GPU index (neither the option nor " + HeadlessGL.GPU_VARIABLE
                        + ") for the automatic choice");
            }
            Device d = devices.get(gpuIndex);
            return initialise(platformDisplay(EGL_PLATFORM_DEVICE_EXT, d.handle()), deviceDescription(d, devices));
        }
        List<String> failures = new ArrayList<>();
        if (platformDevice) {
            for (Device d : devices) {
                if (!d.software()) {
                    EglDisplay display = tryInitialise(platformDisplay(EGL_PLATFORM_DEVICE_EXT, d.handle()),
                            deviceDescription(d, devices), failures);
                    if (display != null) {
                        return display;
                    }
                }
            }
        }
        if (client.contains("EGL_MESA_platform_surfaceless")) {
            EglDisplay display = tryInitialise(platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, 0L), "EGL surfaceless",
                    failures);
            if (display != null) {
                return display;
            }
        }
        if (platformDevice) {
            for (Device d : devices) {
                if (d.software()) {
                    EglDisplay display = tryInitialise(platformDisplay(EGL_PLATFORM_DEVICE_EXT, d.handle()),
                            deviceDescription(d, devices), failures);
                    if (display != null) {
                        return display;
                    }
                }
            }
        }
        EglDisplay display = tryInitialise(EGL10.eglGetDisplay(org.lwjgl.egl.EGL14.EGL_DEFAULT_DISPLAY), "EGL default display",
                failures);
        if (display != null) {
            return display;
        }
        throw new UserInputException("no EGL display initialises (" + String.join("; ", failures) + "): install "
                + "libegl-mesa0 libgl1-mesa-dri, or a GPU driver's EGL");
    }

    private static String deviceDescription(Device d, List<Device> all) {
        return "EGL device " + d.index() + " of " + all.size() + " (" + d.description() + ")";
    }

    /** The client extensions (EGL_NO_DISPLAY); empty where the EGL has none. */
    static Set<String> clientExtensions() {
        String list = EGL10.eglQueryString(EGL10.EGL_NO_DISPLAY, EGL10.EGL_EXTENSIONS);
        EGL10.eglGetError(); // an EGL without client extensions answers EGL_BAD_DISPLAY: not an error here
        return list == null ? Set.of() : Set.copyOf(Arrays.asList(list.trim().split("\\s+")));
    }

    /** Every EGL device, in the order {@code eglQueryDevicesEXT} gives (the order {@code --gpu N} counts in). */
    static List<Device> devices() {
        int[] count = new int[1];
        if (!EXTDeviceEnumeration.eglQueryDevicesEXT(null, count) || count[0] == 0) {
            return List.of();
        }
        PointerBuffer handles = PointerBuffer.allocateDirect(count[0]);
        if (!EXTDeviceEnumeration.eglQueryDevicesEXT(handles, count)) {
            return List.of();
        }
        List<Device> devices = new ArrayList<>();
        for (int i = 0; i < count[0]; i++) {
            long device = handles.get(i);
            String extensions = EXTDeviceQuery.eglQueryDeviceStringEXT(device, EGL10.EGL_EXTENSIONS);
            Set<String> ext = Set.copyOf(Arrays.asList((extensions == null ? "" : extensions.trim()).split("\\s+")));
            boolean software = ext.contains("EGL_MESA_device_software");
            List<String> parts = new ArrayList<>();
            if (ext.contains("EGL_EXT_device_query_name")) {
                add(parts, EXTDeviceQuery.eglQueryDeviceStringEXT(device, EGL_RENDERER_EXT));
            }
            if (ext.contains("EGL_EXT_device_drm_render_node")) {
                add(parts, EXTDeviceQuery.eglQueryDeviceStringEXT(device, EGL_DRM_RENDER_NODE_FILE_EXT));
            } else if (ext.contains("EGL_EXT_device_drm")) {
                add(parts, EXTDeviceQuery.eglQueryDeviceStringEXT(device, EGL_DRM_DEVICE_FILE_EXT));
            }
            if (ext.contains("EGL_NV_device_cuda")) {
                parts.add("NVIDIA CUDA device");
            }
            if (software) {
                parts.add("Mesa software rasteriser");
            }
            EGL10.eglGetError(); // a device that answers none of the queries is still listed
            devices.add(new Device(i, device, parts.isEmpty() ? "unnamed" : String.join(", ", parts), software));
        }
        return devices;
    }

    private static void add(List<String> parts, String value) {
        if (value != null && !value.isBlank()) {
            parts.add(value);
        }
    }

    /**
     * eglGetPlatformDisplay through its raw entry point: LWJGL's checked wrapper refuses the null native display
     * that EGL_PLATFORM_SURFACELESS_MESA requires.
     */
    private static long platformDisplay(int platform, long nativeDisplay) {
        long function = EGL.getCapabilities().eglGetPlatformDisplay;
        if (function == 0L) {
            function = EGL.getCapabilities().eglGetPlatformDisplayEXT;
        }
        if (function == 0L) {
            return EGL10.EGL_NO_DISPLAY;
        }
        return JNI.callPPP(platform, nativeDisplay, 0L, function);
    }

    private static EglDisplay tryInitialise(long handle, String description, List<String> failures) {
        try {
            return initialise(handle, description);
        } catch (UserInputException e) {
            failures.add(e.getMessage());
            return null;
        }
    }

    private static EglDisplay initialise(long handle, String description) {
        if (handle == EGL10.EGL_NO_DISPLAY) {
            throw new UserInputException(description + ": no display (" + EglContext.errorName(EGL10.eglGetError())
                    + ")");
        }
        int[] major = new int[1];
        int[] minor = new int[1];
        if (!EGL10.eglInitialize(handle, major, minor)) {
            throw new UserInputException(description + ": eglInitialize failed ("
                    + EglContext.errorName(EGL10.eglGetError()) + ")");
        }
        return new EglDisplay(handle, description, new int[] {major[0], minor[0]});
    }

    /** Ends this display's use in the process (at exit: see {@link HeadlessGL}). */
    void terminate() {
        EGL10.eglTerminate(handle);
    }

    boolean has(String extension) {
        return extensions.contains(extension);
    }

    boolean atLeastEgl15() {
        return eglVersion[0] > 1 || (eglVersion[0] == 1 && eglVersion[1] >= 5);
    }
}
