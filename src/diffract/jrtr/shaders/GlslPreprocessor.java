package diffract.jrtr.shaders;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Prepares GLSL for the driver, which has no file system: injects {@code #define NAME VALUE} lines right after
 * the {@code #version} line (GLSL requires #version first) and replaces each {@code #include "file.glsl"} line by
 * that file's text, recursively. Include paths are relative to the including file's folder, or to the shader
 * root when they start with '/'. Each file is included at most once per shader (like {@code #pragma once}),
 * which also stops include cycles. Includes are expanded textually, before the GLSL preprocessor runs, so an
 * {@code #include} inside {@code #if 0} is still expanded.
 */
public final class GlslPreprocessor {
    private static final Pattern VERSION = Pattern.compile("^\\s*#\\s*version\\b.*");
    private static final Pattern INCLUDE = Pattern.compile("^\\s*#\\s*include\\s+\"([^\"]+)\"\\s*(//.*)?$");
    private static final Pattern INCLUDE_LIKE = Pattern.compile("^\\s*#\\s*include\\b.*");
    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

    /** Pseudo file name for the injected define lines in diagnostics. */
    public static final String DEFINES_FILE = "<defines>";

    private final ShaderSourceRoot root;

    public GlslPreprocessor(ShaderSourceRoot root) {
        this.root = root;
    }

    /** Preprocesses {@code path} with the given defines (applied in name order, so output is deterministic). */
    public PreprocessedSource process(String path, Map<String, String> defines) {
        String file = ShaderSourceRoot.normalize(path);
        Map<String, String> sortedDefines = new TreeMap<>(defines);
        for (Map.Entry<String, String> define : sortedDefines.entrySet()) {
            if (!IDENTIFIER.matcher(define.getKey()).matches()) {
                throw new ShaderException("invalid #define name '" + define.getKey() + "' for " + file);
            }
            if (define.getValue().contains("\n") || define.getValue().contains("\r")) {
                throw new ShaderException("#define " + define.getKey() + " value must be one line");
            }
        }
        Output out = new Output();
        List<String> lines = splitLines(root.read(file));
        int versionIndex = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (VERSION.matcher(lines.get(i)).matches()) {
                versionIndex = i;
                break;
            }
        }
        if (versionIndex < 0) {
            throw new ShaderException(file + ": no #version line (GLSL needs one, e.g. #version 330 core)");
        }
        Set<String> included = new HashSet<>();
        included.add(file);
        for (int i = 0; i <= versionIndex; i++) {
            out.line(lines.get(i), file, i + 1);
        }
        int defineLine = 1;
        for (Map.Entry<String, String> define : sortedDefines.entrySet()) {
            out.line("#define " + define.getKey() + " " + define.getValue(), DEFINES_FILE, defineLine++);
        }
        expand(file, lines, versionIndex + 1, out, included);
        return new PreprocessedSource(file, out.text.toString(), out.map);
    }

    private void expand(String file, List<String> lines, int from, Output out, Set<String> included) {
        for (int i = from; i < lines.size(); i++) {
            String line = lines.get(i);
            Matcher include = INCLUDE.matcher(line);
            if (include.matches()) {
                String target = resolve(file, include.group(1));
                if (included.add(target)) {
                    String text;
                    try {
                        text = root.read(target);
                    } catch (ShaderException e) {
                        throw new ShaderException(file + ":" + (i + 1) + ": cannot include \"" + include.group(1)
                                + "\": " + e.getMessage());
                    }
                    List<String> includedLines = splitLines(text);
                    for (int k = 0; k < includedLines.size(); k++) {
                        if (VERSION.matcher(includedLines.get(k)).matches()) {
                            throw new ShaderException(target + ":" + (k + 1)
                                    + ": #version in an included file (only the top-level shader may have one)");
                        }
                    }
                    expand(target, includedLines, 0, out, included);
                }
                // keep the line count stable for readers of the preprocessed text: the directive becomes a comment
                out.line("// " + line.trim(), file, i + 1);
            } else if (INCLUDE_LIKE.matcher(line).matches()) {
                throw new ShaderException(file + ":" + (i + 1) + ": malformed #include (expected #include \"file\"): "
                        + line.trim());
            } else {
                out.line(line, file, i + 1);
            }
        }
    }

    private static String resolve(String includingFile, String includePath) {
        if (includePath.startsWith("/")) {
            return ShaderSourceRoot.normalize(includePath);
        }
        int slash = includingFile.lastIndexOf('/');
        String folder = slash < 0 ? "" : includingFile.substring(0, slash + 1);
        return ShaderSourceRoot.normalize(folder + includePath);
    }

    private static List<String> splitLines(String text) {
        List<String> lines = new ArrayList<>(List.of(text.split("\r\n|\r|\n", -1)));
        if (!lines.isEmpty() && lines.get(lines.size() - 1).isEmpty()) {
            lines.remove(lines.size() - 1); // the final newline does not start another line
        }
        return lines;
    }

    private static final class Output {
        final StringBuilder text = new StringBuilder();
        final SourceMap map = new SourceMap();

        void line(String line, String file, int lineNumber) {
            text.append(line).append('\n');
            map.add(file, lineNumber);
        }
    }
}
