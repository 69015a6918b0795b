package diffract.geometry;

import diffract.util.UserInputException;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads a Wavefront OBJ mesh for the diffraction shaders: {@code v}, {@code vt}, {@code vn} and {@code f} lines
 * (v, v/vt, v//vn, v/vt/vn corners; negative indices count back from the latest element; polygons are
 * triangulated as fans), and the thesis' per-vertex tangent lines {@code tg x y z}, one per {@code v} line in the
 * same order. Other statements (o, g, s, usemtl, mtllib, l, ...) are ignored: they do not change the geometry.
 *
 * <p>Normals are the file's {@code vn} when every face corner names one, else smooth area-weighted normals.
 * Tangents come from the {@link TangentSource}: the explicit {@code tg} lines, dP/du from the texture coordinates,
 * or a world direction; each is projected onto its vertex's tangent plane and normalised. Every problem is one
 * {@link UserInputException} line {@code FILE:LINE: what is wrong}.
 */
public final class ObjReader {
    private final String name;
    private final List<double[]> positions = new ArrayList<>();
    private final List<double[]> uvs = new ArrayList<>();
    private final List<double[]> normals = new ArrayList<>();
    private final List<double[]> tangentLines = new ArrayList<>();
    /** One mesh vertex per distinct (v, vt, vn) corner: a seam in UVs or normals splits a position. */
    private final Map<List<Integer>, Integer> corners = new HashMap<>();
    private final List<int[]> vertexCorners = new ArrayList<>();
    private final List<Integer> triangles = new ArrayList<>();
    private int firstFaceLine;
    private int cornerWithoutUvLine;
    private int cornerWithoutNormalLine;

    private ObjReader(String name) {
        this.name = name;
    }

    public static Mesh read(Path file, TangentSource tangents) {
        String text;
        try {
            text = new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UserInputException("cannot read OBJ file " + file + ": " + e.getMessage(), e);
        }
        return parse(text, file.toString(), tangents);
    }

    /** @param name how messages name the file */
    public static Mesh parse(String text, String name, TangentSource tangents) {
        ObjReader reader = new ObjReader(name);
        String[] lines = text.split("\r?\n|\r", -1);
        for (int i = 0; i < lines.length; i++) {
            reader.statement(lines[i], i + 1);
        }
        return reader.mesh(tangents);
    }

    private UserInputException problem(int line, String what) {
        return new UserInputException(name + ":" + line + ": " + what);
    }

    private void statement(String rawLine, int line) {
        int hash = rawLine.indexOf('#');
        String content = (hash >= 0 ? rawLine.substring(0, hash) : rawLine).trim();
        if (content.isEmpty()) {
            return;
        }
        String[] fields = content.split("\\s+");
        switch (fields[0]) {
            case "v":
                positions.add(numbers(fields, 3, 4, line));
                break;
            case "vt":
                uvs.add(numbers(fields, 1, 3, line));
                break;
            case "vn":
                normals.add(numbers(fields, 3, 3, line));
                break;
            case "tg":
                tangentLines.add(numbers(fields, 3, 3, line));
                break;
            case "f":
                face(fields, line);
                break;
            default:
                break; // o, g, s, usemtl, mtllib, l, p, ...: no effect on the surface frames
        }
    }

    private double[] numbers(String[] fields, int min, int max, int line) {
        int count = fields.length - 1;
        if (count < min || count > max) {
            throw problem(line, "'" + fields[0] + "' needs " + (min == max ? min : min + " to " + max)
                    + " numbers, got " + count);
        }
        double[] values = new double[Math.max(count, 3)];
        for (int k = 0; k < count; k++) {
            try {
                values[k] = Double.parseDouble(fields[k + 1]);
            } catch (NumberFormatException e) {
                throw problem(line, "malformed number '" + fields[k + 1] + "' in a '" + fields[0] + "' line");
            }
            // the mesh keeps floats: a double beyond their range would become infinite there
            if (!Double.isFinite(values[k]) || !Float.isFinite((float) values[k])) {
                throw problem(line, "'" + fields[k + 1] + "' is not a finite number (a mesh's numbers stay within"
                        + " +-3.4e38)");
            }
        }
        return values;
    }

    private void face(String[] fields, int line) {
        if (positions.isEmpty()) {
            throw problem(line, "face before any vertex: 'v' lines must come before the 'f' lines that use them");
        }
        if (fields.length < 4) {
            throw problem(line, "a face needs at least 3 corners, got " + (fields.length - 1));
        }
        if (firstFaceLine == 0) {
            firstFaceLine = line;
        }
        int[] vertices = new int[fields.length - 1];
        for (int k = 1; k < fields.length; k++) {
            vertices[k - 1] = corner(fields[k], line);
        }
        for (int k = 1; k + 1 < vertices.length; k++) {
            triangles.add(vertices[0]);
            triangles.add(vertices[k]);
            triangles.add(vertices[k + 1]);
        }
    }

    private int corner(String text, int line) {
        String[] parts = text.split("/", -1);
        if (parts.length > 3 || parts[0].isEmpty()) {
            throw problem(line, "malformed face corner '" + text + "': use v, v/vt, v//vn or v/vt/vn");
        }
        int v = index(parts[0], positions.size(), "vertex", text, line);
        int vt = parts.length > 1 && !parts[1].isEmpty() ? index(parts[1], uvs.size(), "texture coordinate", text, line)
                : -1;
        int vn = parts.length > 2 && !parts[2].isEmpty() ? index(parts[2], normals.size(), "normal", text, line) : -1;
        if (vt < 0 && cornerWithoutUvLine == 0) {
            cornerWithoutUvLine = line;
        }
        if (vn < 0 && cornerWithoutNormalLine == 0) {
            cornerWithoutNormalLine = line;
        }
        return corners.computeIfAbsent(List.of(v, vt, vn), key -> {
            vertexCorners.add(new int[] {v, vt, vn});
            return vertexCorners.size() - 1;
        });
    }

    /** A 1-based index, or a negative one counting back from the latest of {@code count} elements; 0-based out. */
    private int index(String text, int count, String what, String corner, int line) {
        int index;
        try {
            index = Integer.parseInt(text);
        } catch (NumberFormatException e) {
            throw problem(line, "malformed " + what + " index '" + text + "' in face corner '" + corner + "'");
        }
        int zeroBased = index > 0 ? index - 1 : count + index;
        if (index == 0 || zeroBased < 0 || zeroBased >= count) {
            throw problem(line, what + " index " + index + " in face corner '" + corner + "' is out of range: "
                    + count + " " + (what.equals("vertex") ? "vertices" : what + "s") + " defined so far (indices 1.." + count
                    + " or -1..-" + count + ")");
        }
        return zeroBased;
    }

    private Mesh mesh(TangentSource tangentSource) {
        if (triangles.isEmpty()) {
            throw problem(1, "no faces: an OBJ mesh needs 'f' lines");
        }
        int n = vertexCorners.size();
        float[] p = new float[3 * n];
        float[] uv = cornerWithoutUvLine == 0 ? new float[2 * n] : null;
        for (int i = 0; i < n; i++) {
            int[] c = vertexCorners.get(i);
            double[] position = positions.get(c[0]);
            for (int k = 0; k < 3; k++) {
                p[3 * i + k] = (float) position[k];
            }
            if (uv != null) {
                uv[2 * i] = (float) uvs.get(c[1])[0];
                uv[2 * i + 1] = (float) uvs.get(c[1])[1];
            }
        }
        int[] t = triangles.stream().mapToInt(Integer::intValue).toArray();
        float[] normalFloats = SurfaceFrames.toFloats(normals(p, t));
        Vec3[] directions = tangentDirections(tangentSource, p, uv, t);
        return Mesh.of(p, normalFloats, SurfaceFrames.tangentsFrom(normalFloats, directions), uv, t);
    }

    private Vec3[] normals(float[] p, int[] t) {
        if (cornerWithoutNormalLine != 0) {
            return SurfaceFrames.smoothNormals(p, t);
        }
        Vec3[] out = new Vec3[vertexCorners.size()];
        for (int i = 0; i < out.length; i++) {
            double[] n = normals.get(vertexCorners.get(i)[2]);
            out[i] = new Vec3(n[0], n[1], n[2]);
            if (out[i].length() == 0) {
                throw problem(1, "normal " + (vertexCorners.get(i)[2] + 1) + " ('vn' line) has zero length");
            }
        }
        return out;
    }

    private Vec3[] tangentDirections(TangentSource source, float[] p, float[] uv, int[] t) {
        if (source instanceof TangentSource.Explicit) {
            if (tangentLines.size() != positions.size()) {
                throw problem(1, "tangents \"explicit\" need one 'tg x y z' line per 'v' line: " + tangentLines.size()
                        + " tg lines for " + positions.size() + " vertices");
            }
            Vec3[] out = new Vec3[vertexCorners.size()];
            for (int i = 0; i < out.length; i++) {
                double[] d = tangentLines.get(vertexCorners.get(i)[0]);
                out[i] = new Vec3(d[0], d[1], d[2]);
            }
            return out;
        }
        if (source instanceof TangentSource.FromUvs) {
            if (uv == null) {
                throw problem(cornerWithoutUvLine, "tangents from UVs need a texture coordinate (v/vt) at every face "
                        + "corner; this face has none (or use tangents \"explicit\" or a projected direction)");
            }
            return SurfaceFrames.uvTangentDirections(p, uv, t);
        }
        return SurfaceFrames.constant(((TangentSource.Projected) source).direction(), vertexCorners.size());
    }
}
