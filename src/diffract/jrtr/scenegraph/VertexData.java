package diffract.jrtr.scenegraph;

import java.util.Collections;
import java.util.EnumMap;
import java.util.Map;

/**
 * Triangle mesh data on the CPU: per-vertex attributes (at least {@link VertexAttribute#POSITION}) and an
 * index list, three indices per triangle. Immutable after construction (arrays are copied), so the GPU copy
 * made once by the render context never goes stale.
 */
public final class VertexData {
    private final int vertexCount;
    private final Map<VertexAttribute, float[]> attributes;
    private final int[] indices;

    private VertexData(int vertexCount, Map<VertexAttribute, float[]> attributes, int[] indices) {
        this.vertexCount = vertexCount;
        this.attributes = Collections.unmodifiableMap(attributes);
        this.indices = indices;
    }

    /** Starts a mesh of {@code vertexCount} vertices. */
    public static Builder builder(int vertexCount) {
        return new Builder(vertexCount);
    }

    public int vertexCount() {
        return vertexCount;
    }

    public boolean has(VertexAttribute attribute) {
        return attributes.containsKey(attribute);
    }

    /** A copy of the attribute's floats, {@code components()} per vertex; throws if absent. */
    public float[] attribute(VertexAttribute attribute) {
        return attributeView(attribute).clone();
    }

    /** Attribute floats without copying, for the GPU upload. */
    public float[] attributeView(VertexAttribute attribute) {
        float[] values = attributes.get(attribute);
        if (values == null) {
            throw new IllegalArgumentException("mesh has no " + attribute.glslName() + " attribute");
        }
        return values;
    }

    /** The attributes present. */
    public Iterable<VertexAttribute> attributes() {
        return attributes.keySet();
    }

    public int indexCount() {
        return indices.length;
    }

    /** A copy of the triangle indices. */
    public int[] indices() {
        return indices.clone();
    }

    public int[] indicesView() {
        return indices;
    }

    /** Collects attributes and indices, checking sizes. */
    public static final class Builder {
        private final int vertexCount;
        private final Map<VertexAttribute, float[]> attributes = new EnumMap<>(VertexAttribute.class);
        private int[] indices;

        private Builder(int vertexCount) {
            if (vertexCount <= 0) {
                throw new IllegalArgumentException("a mesh needs at least one vertex, got " + vertexCount);
            }
            this.vertexCount = vertexCount;
        }

        public Builder attribute(VertexAttribute attribute, float... values) {
            int expected = vertexCount * attribute.components();
            if (values.length != expected) {
                throw new IllegalArgumentException(attribute.glslName() + ": expected " + expected + " floats ("
                        + vertexCount + " vertices x " + attribute.components() + "), got " + values.length);
            }
            attributes.put(attribute, values.clone());
            return this;
        }

        public Builder positions(float... xyz) {
            return attribute(VertexAttribute.POSITION, xyz);
        }

        public Builder normals(float... xyz) {
            return attribute(VertexAttribute.NORMAL, xyz);
        }

        public Builder tangents(float... xyz) {
            return attribute(VertexAttribute.TANGENT, xyz);
        }

        public Builder texcoords(float... uv) {
            return attribute(VertexAttribute.TEXCOORD, uv);
        }

        /** Triangle list: three indices per triangle, each in [0, vertexCount). */
        public Builder indices(int... triangleIndices) {
            if (triangleIndices.length == 0 || triangleIndices.length % 3 != 0) {
                throw new IllegalArgumentException("index count must be a positive multiple of 3, got "
                        + triangleIndices.length);
            }
            for (int index : triangleIndices) {
                if (index < 0 || index >= vertexCount) {
                    throw new IllegalArgumentException("index " + index + " outside [0, " + vertexCount + ")");
                }
            }
            this.indices = triangleIndices.clone();
            return this;
        }

        public VertexData build() {
            if (!attributes.containsKey(VertexAttribute.POSITION)) {
                throw new IllegalStateException("a mesh needs positions");
            }
            if (indices == null) {
                throw new IllegalStateException("a mesh needs indices");
            }
            return new VertexData(vertexCount, new EnumMap<>(attributes), indices);
        }
    }
}
