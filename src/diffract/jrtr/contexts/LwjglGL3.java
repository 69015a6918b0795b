package diffract.jrtr.contexts;

import com.jogamp.opengl.GL3;
import diffract.jrtr.gl.GLErrors;
import org.lwjgl.opengl.GL11C;
import org.lwjgl.opengl.GL12C;
import org.lwjgl.opengl.GL13C;
import org.lwjgl.opengl.GL14C;
import org.lwjgl.opengl.GL15C;
import org.lwjgl.opengl.GL20C;
import org.lwjgl.opengl.GL21C;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.opengl.GL31C;
import org.lwjgl.opengl.GL32C;
import org.lwjgl.opengl.GL33C;
import org.lwjgl.opengl.GL40C;
import org.lwjgl.opengl.GL41C;
import org.lwjgl.opengl.GL42C;
import org.lwjgl.opengl.GL43C;
import org.lwjgl.opengl.GL44C;
import org.lwjgl.opengl.GL45C;
import org.lwjgl.opengl.GL46C;
import org.lwjgl.system.MemoryUtil;

import java.lang.reflect.InvocationHandler;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Proxy;
import java.nio.Buffer;
import java.nio.ByteBuffer;
import java.nio.DoubleBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.LongBuffer;
import java.nio.ShortBuffer;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * JOGL's {@link GL3} interface answered by LWJGL's OpenGL bindings, for contexts JOGL cannot create (headless EGL,
 * {@link EglContext}): the engine keeps issuing its calls through {@code GL3}, whatever made the context current.
 *
 * <p>Each JOGL method is bound on first use to the LWJGL core function of the same name (GL11C to GL46C), by the
 * C signature both bindings mirror:
 * <ul>
 *   <li>only primitive parameters: the LWJGL method with the same parameter types;</li>
 *   <li>{@code String} parameters: the LWJGL method taking {@code CharSequence} there;</li>
 *   <li>arrays with their offset ({@code int[] a, int offset}) and NIO buffers: LWJGL's raw {@code nglName} with a
 *       native address in their place. Arrays and heap buffers are copied to native memory for the call (and back
 *       for {@code glGen*}, {@code glGet*} and {@code glRead*}, whose pointers are outputs); direct buffers are
 *       passed as they are, from their position, as JOGL does.</li>
 * </ul>
 * {@code glShaderSource(int, int, String[], int[], int)} is the one JOGL signature with no C twin and is written
 * out. Of JOGL's own helpers, the version queries and {@code isExtensionAvailable} (from the context's
 * {@code GL_EXTENSIONS} list) are answered; the others throw {@link UnsupportedOperationException} naming the
 * method. The calls need this context current on the thread
 * (LWJGL's capabilities set), which {@link EglContext#makeCurrent} does.
 */
final class LwjglGL3 implements InvocationHandler {
    private static final Class<?>[] CORE_CLASSES = {GL46C.class, GL45C.class, GL44C.class, GL43C.class, GL42C.class,
        GL41C.class, GL40C.class, GL33C.class, GL32C.class, GL31C.class, GL30C.class, GL21C.class, GL20C.class,
        GL15C.class, GL14C.class, GL13C.class, GL12C.class, GL11C.class};
    /** LWJGL's static core functions by name (every overload), collected once. */
    private static final Map<String, List<Method>> CORE_FUNCTIONS = coreFunctions();
    /**
     * {@code -Ddiffract.glTrace=true}: each call is followed by {@code glGetError}, and an error is printed with the
     * call that raised it and cleared. A driver stricter than Mesa's then names the offending call, where the
     * engine's checks ({@link GLErrors}) only notice an error at their next check.
     */
    private static final boolean TRACE = Boolean.getBoolean("diffract.glTrace");
    /** JOGL method to its binding; the bindings are the same for every context. */
    private static final Map<Method, Call> BINDINGS = new ConcurrentHashMap<>();

    private final GL3 proxy;
    private final String platform;
    private final int[] version;
    /** The context's extensions, read at the first question (the context is current then). */
    private volatile Set<String> extensions;

    private LwjglGL3(String platform, int[] version) {
        this.platform = platform;
        this.version = version.clone();
        this.proxy = (GL3) Proxy.newProxyInstance(LwjglGL3.class.getClassLoader(),
                new Class<?>[] {GL3.class, GLPlatform.class}, this);
    }

    /**
     * A {@link GL3} for the context current on this thread; {@code platform} describes it (e.g. "EGL surfaceless"),
     * {@code version} is its OpenGL {major, minor}.
     */
    static GL3 create(String platform, int[] version) {
        return new LwjglGL3(platform, version).proxy;
    }

    /** What a JOGL {@code GL} knows of itself beyond the GL functions; the proxy answers it. */
    interface GLPlatform {
        /** Which window system or platform gave the context, e.g. "EGL surfaceless". */
        String platformDescription();
    }

    @Override
    public Object invoke(Object self, Method method, Object[] args) throws Throwable {
        String name = method.getName();
        if (method.getDeclaringClass() == Object.class) {
            return switch (name) {
                case "hashCode" -> System.identityHashCode(self);
                case "equals" -> self == args[0];
                default -> "LwjglGL3[" + platform + ", OpenGL " + version[0] + "." + version[1] + "]";
            };
        }
        if (method.getDeclaringClass() == GLPlatform.class) {
            return platform;
        }
        if (!name.startsWith("gl") || name.length() < 3 || !Character.isUpperCase(name.charAt(2))) {
            return glBase(method, args);
        }
        Object[] actual = args == null ? new Object[0] : args;
        Object result = BINDINGS.computeIfAbsent(method, LwjglGL3::bind).call(actual);
        if (TRACE && !name.equals("glGetError")) {
            for (int error = GL11C.glGetError(); error != GL11C.GL_NO_ERROR; error = GL11C.glGetError()) {
                System.err.println("diffract: GL trace: " + GLErrors.name(error) + " after " + name
                        + java.util.Arrays.deepToString(actual));
            }
        }
        return result;
    }

    /** JOGL's GLBase helpers the engine uses; the rest are JOGL-internal and not offered here. */
    private Object glBase(Method method, Object[] args) {
        String name = method.getName();
        boolean atLeast32 = version[0] > 3 || (version[0] == 3 && version[1] >= 2);
        switch (name) {
            case "getGL", "getGL3", "getGL2GL3", "getGL2ES2", "getGL3ES3", "getGL2ES3", "getDownstreamGL",
                    "getRootGL" -> {
                return proxy;
            }
            case "isGL3", "isGL3core", "isGL2GL3", "isGL2ES2", "isGL2ES3", "isGL3ES3", "isGLcore" -> {
                return atLeast32;
            }
            case "isGL4", "isGL4core" -> {
                return version[0] >= 4;
            }
            case "isGL", "hasGLSL" -> {
                return true;
            }
            case "isGLES", "isGLES1", "isGLES2", "isGLES3", "isGLES31", "isGLES32", "isGL2", "isGL3bc", "isGL4bc",
                    "isGL2ES1", "isGL4ES3", "isGLES2Compatible", "isGLES3Compatible", "isGLES31Compatible",
                    "isGLES32Compatible", "isTextureFormatBGRA8888Available" -> {
                return false;
            }
            case "getContext" -> {
                return null; // not a JOGL context: callers identify it by this GL object
            }
            case "isExtensionAvailable" -> {
                return extensions().contains((String) args[0]);
            }
            default -> throw new UnsupportedOperationException(method.getName()
                    + " is a JOGL helper the headless EGL context does not offer");
        }
    }

    /** The core profile's extension list: GL_NUM_EXTENSIONS names, one glGetStringi each. */
    private Set<String> extensions() {
        Set<String> known = extensions;
        if (known == null) {
            known = new HashSet<>();
            int count = GL11C.glGetInteger(GL30C.GL_NUM_EXTENSIONS);
            for (int i = 0; i < count; i++) {
                known.add(GL30C.glGetStringi(GL11C.GL_EXTENSIONS, i));
            }
            extensions = known;
        }
        return known;
    }

    private static Map<String, List<Method>> coreFunctions() {
        Map<String, List<Method>> functions = new HashMap<>();
        for (Class<?> c : CORE_CLASSES) {
            for (Method m : c.getDeclaredMethods()) {
                if (Modifier.isStatic(m.getModifiers()) && Modifier.isPublic(m.getModifiers())) {
                    functions.computeIfAbsent(m.getName(), k -> new ArrayList<>()).add(m);
                }
            }
        }
        return functions;
    }

    /** One bound JOGL method. */
    private interface Call {
        Object call(Object[] args) throws Throwable;
    }

    private static Call bind(Method jogl) {
        Class<?>[] types = jogl.getParameterTypes();
        String name = jogl.getName();
        if (name.equals("glShaderSource") && types.length == 5 && types[2] == String[].class) {
            return args -> {
                String[] sources = (String[]) args[2];
                GL20C.glShaderSource((Integer) args[0], java.util.Arrays.copyOf(sources, (Integer) args[1]));
                return null;
            };
        }
        boolean hasPointers = false;
        boolean hasStrings = false;
        for (Class<?> t : types) {
            hasPointers |= t.isArray() || Buffer.class.isAssignableFrom(t);
            hasStrings |= t == String.class;
        }
        if (!hasPointers) {
            Class<?>[] wanted = types.clone();
            for (int i = 0; i < wanted.length; i++) {
                if (wanted[i] == String.class) {
                    wanted[i] = CharSequence.class;
                }
            }
            Method target = find(name, wanted, jogl.getReturnType());
            return args -> invoke(target, args);
        }
        if (hasStrings) {
            throw unsupported(jogl);
        }
        List<Class<?>> raw = new ArrayList<>();
        List<Integer> pointerAt = new ArrayList<>();
        for (int i = 0; i < types.length; i++) {
            if (types[i].isArray()) {
                if (i + 1 >= types.length || types[i + 1] != int.class) {
                    throw unsupported(jogl);
                }
                pointerAt.add(raw.size());
                raw.add(long.class);
                i++; // the array's offset travels with it
            } else if (Buffer.class.isAssignableFrom(types[i])) {
                pointerAt.add(raw.size());
                raw.add(long.class);
            } else {
                raw.add(types[i]);
            }
        }
        Method target = find("n" + name, raw.toArray(new Class<?>[0]), jogl.getReturnType());
        boolean writesBack = name.startsWith("glGet") || name.startsWith("glGen") || name.startsWith("glRead");
        return args -> callWithPointers(target, types, args, raw.size(), writesBack);
    }

    private static Method find(String name, Class<?>[] parameters, Class<?> returnType) {
        for (Method m : CORE_FUNCTIONS.getOrDefault(name, List.of())) {
            if (java.util.Arrays.equals(m.getParameterTypes(), parameters)
                    && (returnType == void.class || m.getReturnType() == returnType)) {
                return m;
            }
        }
        throw new UnsupportedOperationException("no OpenGL core function " + name + java.util.Arrays.toString(parameters)
                + " in LWJGL for the headless EGL context");
    }

    private static UnsupportedOperationException unsupported(Method jogl) {
        return new UnsupportedOperationException("JOGL's " + jogl.getName()
                + java.util.Arrays.toString(jogl.getParameterTypes()) + " has no binding on the headless EGL context");
    }

    private static Object invoke(Method target, Object[] args) throws Throwable {
        try {
            return target.invoke(null, args);
        } catch (InvocationTargetException e) {
            throw e.getCause();
        }
    }

    /** Calls {@code nglName} with native addresses for the arrays and buffers of {@code args}. */
    private static Object callWithPointers(Method target, Class<?>[] types, Object[] args, int rawCount,
                                           boolean writesBack) throws Throwable {
        Object[] raw = new Object[rawCount];
        List<Runnable> after = new ArrayList<>();
        try {
            int r = 0;
            for (int i = 0; i < types.length; i++) {
                Object arg = args[i];
                if (types[i].isArray()) {
                    int offset = (Integer) args[i + 1];
                    raw[r++] = arrayAddress(arg, offset, writesBack, after);
                    i++;
                } else if (Buffer.class.isAssignableFrom(types[i])) {
                    raw[r++] = bufferAddress((Buffer) arg, writesBack, after);
                } else {
                    raw[r++] = arg;
                }
            }
            return invoke(target, raw);
        } finally {
            for (Runnable step : after) {
                step.run();
            }
        }
    }

    /** Copies {@code array[offset..]} to native memory; {@code after} copies it back (if asked) and frees it. */
    private static long arrayAddress(Object array, int offset, boolean writeBack, List<Runnable> after) {
        if (array == null) {
            return 0L;
        }
        int length = java.lang.reflect.Array.getLength(array) - offset;
        if (length <= 0) {
            throw new IndexOutOfBoundsException("offset " + offset + " past the array's end");
        }
        ByteBuffer memory;
        if (array instanceof int[] a) {
            memory = MemoryUtil.memAlloc(length * Integer.BYTES);
            memory.asIntBuffer().put(a, offset, length);
            if (writeBack) {
                after.add(() -> memory.asIntBuffer().get(a, offset, length));
            }
        } else if (array instanceof float[] a) {
            memory = MemoryUtil.memAlloc(length * Float.BYTES);
            memory.asFloatBuffer().put(a, offset, length);
            if (writeBack) {
                after.add(() -> memory.asFloatBuffer().get(a, offset, length));
            }
        } else if (array instanceof long[] a) {
            memory = MemoryUtil.memAlloc(length * Long.BYTES);
            memory.asLongBuffer().put(a, offset, length);
            if (writeBack) {
                after.add(() -> memory.asLongBuffer().get(a, offset, length));
            }
        } else if (array instanceof double[] a) {
            memory = MemoryUtil.memAlloc(length * Double.BYTES);
            memory.asDoubleBuffer().put(a, offset, length);
            if (writeBack) {
                after.add(() -> memory.asDoubleBuffer().get(a, offset, length));
            }
        } else if (array instanceof short[] a) {
            memory = MemoryUtil.memAlloc(length * Short.BYTES);
            memory.asShortBuffer().put(a, offset, length);
            if (writeBack) {
                after.add(() -> memory.asShortBuffer().get(a, offset, length));
            }
        } else if (array instanceof byte[] a) {
            memory = MemoryUtil.memAlloc(length);
            memory.put(0, a, offset, length);
            if (writeBack) {
                after.add(() -> memory.get(0, a, offset, length));
            }
        } else {
            throw new IllegalArgumentException("unsupported array type " + array.getClass().getSimpleName());
        }
        after.add(() -> MemoryUtil.memFree(memory));
        return MemoryUtil.memAddress(memory);
    }

    /**
     * A direct buffer's address at its position; a heap buffer's remaining elements copied to native memory
     * (and back, if asked) for the call.
     */
    private static long bufferAddress(Buffer buffer, boolean writeBack, List<Runnable> after) {
        if (buffer == null) {
            return 0L;
        }
        if (buffer.isDirect()) {
            return MemoryUtil.memAddress(buffer);
        }
        int elements = buffer.remaining();
        int position = buffer.position();
        ByteBuffer memory;
        Runnable back;
        if (buffer instanceof FloatBuffer b) {
            memory = MemoryUtil.memAlloc(elements * Float.BYTES);
            memory.asFloatBuffer().put(b.duplicate());
            back = () -> b.duplicate().position(position).put(memory.asFloatBuffer());
        } else if (buffer instanceof IntBuffer b) {
            memory = MemoryUtil.memAlloc(elements * Integer.BYTES);
            memory.asIntBuffer().put(b.duplicate());
            back = () -> b.duplicate().position(position).put(memory.asIntBuffer());
        } else if (buffer instanceof ByteBuffer b) {
            memory = MemoryUtil.memAlloc(elements);
            memory.put(b.duplicate()).flip();
            back = () -> b.duplicate().position(position).put(memory.duplicate().clear());
        } else if (buffer instanceof ShortBuffer b) {
            memory = MemoryUtil.memAlloc(elements * Short.BYTES);
            memory.asShortBuffer().put(b.duplicate());
            back = () -> b.duplicate().position(position).put(memory.asShortBuffer());
        } else if (buffer instanceof LongBuffer b) {
            memory = MemoryUtil.memAlloc(elements * Long.BYTES);
            memory.asLongBuffer().put(b.duplicate());
            back = () -> b.duplicate().position(position).put(memory.asLongBuffer());
        } else if (buffer instanceof DoubleBuffer b) {
            memory = MemoryUtil.memAlloc(elements * Double.BYTES);
            memory.asDoubleBuffer().put(b.duplicate());
            back = () -> b.duplicate().position(position).put(memory.asDoubleBuffer());
        } else {
            throw new IllegalArgumentException("unsupported buffer type " + buffer.getClass().getSimpleName());
        }
        if (writeBack && !buffer.isReadOnly()) {
            after.add(back);
        }
        after.add(() -> MemoryUtil.memFree(memory));
        return MemoryUtil.memAddress(memory);
    }
}
