package diffract.jrtr.shaders;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Rewrites a driver's shader info log so every position names the original file and line:
 * Mesa {@code 0:12(5): error: ...}, NVIDIA {@code 0(12) : error C0000: ...} and AMD/Intel
 * {@code ERROR: 0:12: ...} all become {@code file.glsl:LINE: ...}. Lines in other formats are kept as they are.
 */
public final class ShaderLogTranslator {
    private static final Pattern MESA = Pattern.compile("^\\s*(\\d+):(\\d+)\\((\\d+)\\):\\s*(.*)$");
    private static final Pattern NVIDIA = Pattern.compile("^\\s*(\\d+)\\((\\d+)\\)\\s*:\\s*(.*)$");
    private static final Pattern AMD_INTEL = Pattern.compile("^\\s*(ERROR|WARNING):\\s*(\\d+):(\\d+):\\s*(.*)$");

    private ShaderLogTranslator() {
    }

    /** One translated diagnostic per non-empty log line. */
    public static List<String> translate(String log, SourceMap map) {
        List<String> out = new ArrayList<>();
        for (String line : log.split("\r\n|\r|\n")) {
            if (line.isBlank()) {
                continue;
            }
            out.add(translateLine(line, map));
        }
        return out;
    }

    static String translateLine(String line, SourceMap map) {
        Matcher m = MESA.matcher(line);
        if (m.matches()) {
            return map.locate(Integer.parseInt(m.group(2))) + ": " + m.group(4);
        }
        m = NVIDIA.matcher(line);
        if (m.matches()) {
            return map.locate(Integer.parseInt(m.group(2))) + ": " + m.group(3);
        }
        m = AMD_INTEL.matcher(line);
        if (m.matches()) {
            String severity = m.group(1).toLowerCase(java.util.Locale.ROOT);
            return map.locate(Integer.parseInt(m.group(3))) + ": " + severity + ": " + m.group(4);
        }
        return line.trim();
    }
}
