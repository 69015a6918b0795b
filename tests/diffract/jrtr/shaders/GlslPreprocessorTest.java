package diffract.jrtr.shaders;

import diffract.jrtr.GlTestSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Define injection, include expansion and the source map, without a GPU. */
class GlslPreprocessorTest {
    @TempDir
    Path dir;

    private PreprocessedSource process(String file, Map<String, String> defines) {
        return new GlslPreprocessor(ShaderSourceRoot.directory(dir)).process(file, defines);
    }

    @Test
    void definesGoRightAfterTheVersionLineInNameOrder() throws Exception {
        GlTestSupport.write(dir, "a.frag", "// header comment\n#version 330 core\nvoid main() {}\n");
        PreprocessedSource source = process("a.frag",
                Map.of("VARIANT_FLSS", "1", "TERMS", "31", "WINDOW_RADIUS", "1"));
        assertEquals(List.of("// header comment", "#version 330 core", "#define TERMS 31",
                "#define VARIANT_FLSS 1", "#define WINDOW_RADIUS 1", "void main() {}"),
                List.of(source.text().split("\n")));
        assertEquals(new SourceMap.Location("a.frag", 2), source.sourceMap().locate(2));
        assertEquals(new SourceMap.Location(GlslPreprocessor.DEFINES_FILE, 1), source.sourceMap().locate(3));
        assertEquals(new SourceMap.Location("a.frag", 3), source.sourceMap().locate(6));
    }

    @Test
    void includesResolveRelativeToTheIncludingFileAndMapBack() throws Exception {
        GlTestSupport.write(dir, "shaders/main.frag",
                "#version 330 core\n#include \"lib/a.glsl\"\nvoid main() {}\n");
        GlTestSupport.write(dir, "shaders/lib/a.glsl", "float a;\n#include \"../common/b.glsl\"\nfloat a2;\n");
        GlTestSupport.write(dir, "shaders/common/b.glsl", "float b;\n");
        PreprocessedSource source = process("shaders/main.frag", Map.of());
        assertEquals(List.of("#version 330 core", "float a;", "float b;", "// #include \"../common/b.glsl\"",
                "float a2;", "// #include \"lib/a.glsl\"", "void main() {}"), List.of(source.text().split("\n")));
        SourceMap map = source.sourceMap();
        assertEquals("shaders/lib/a.glsl:1", map.locate(2).toString());
        assertEquals("shaders/common/b.glsl:1", map.locate(3).toString());
        assertEquals("shaders/lib/a.glsl:3", map.locate(5).toString());
        assertEquals("shaders/main.frag:3", map.locate(7).toString());
        assertEquals("shaders/main.frag:3", map.locate(99).toString(), "past the end maps to the last line");
    }

    @Test
    void eachFileIsIncludedOnceSoCyclesTerminate() throws Exception {
        GlTestSupport.write(dir, "main.frag", "#version 330 core\n#include \"x.glsl\"\n#include \"y.glsl\"\n");
        GlTestSupport.write(dir, "x.glsl", "float x;\n#include \"y.glsl\"\n");
        GlTestSupport.write(dir, "y.glsl", "float y;\n#include \"x.glsl\"\n#include \"main.frag\"\n");
        String text = process("main.frag", Map.of()).text();
        assertEquals(1, text.split("float x;", -1).length - 1);
        assertEquals(1, text.split("float y;", -1).length - 1);
    }

    @Test
    void problemsNameTheFileAndLine() throws Exception {
        GlTestSupport.write(dir, "missing.frag", "#version 330 core\n\n#include \"nowhere.glsl\"\n");
        ShaderException missing = assertThrows(ShaderException.class, () -> process("missing.frag", Map.of()));
        assertTrue(missing.getMessage().startsWith("missing.frag:3: cannot include \"nowhere.glsl\""),
                missing.getMessage());

        GlTestSupport.write(dir, "noversion.frag", "void main() {}\n");
        assertThrows(ShaderException.class, () -> process("noversion.frag", Map.of()));

        GlTestSupport.write(dir, "escape.frag", "#version 330 core\n#include \"../../etc/passwd\"\n");
        assertTrue(assertThrows(ShaderException.class, () -> process("escape.frag", Map.of()))
                .getMessage().contains("leaves the shader root"));

        GlTestSupport.write(dir, "ok.frag", "#version 330 core\n");
        assertThrows(ShaderException.class, () -> process("ok.frag", Map.of("BAD NAME", "1")));
        assertThrows(ShaderException.class, () -> process("ok.frag", Map.of("X", "1\n#define Y")));
    }

    @Test
    void classpathShadersLoad() {
        PreprocessedSource source = new GlslPreprocessor(ShaderSourceRoot.classpath())
                .process("engine/unlit.frag", Map.of("OUTPUT_NORMAL", "1"));
        assertTrue(source.text().contains("vec3 encodeNormal(vec3 n)"), "common.glsl was included");
        assertTrue(source.text().contains("#define OUTPUT_NORMAL 1"));
    }

    @Test
    void driverLogsOfAllFormatsAreTranslated() throws Exception {
        GlTestSupport.write(dir, "m.frag", "#version 330 core\n#include \"inc.glsl\"\nvoid main() {}\n");
        GlTestSupport.write(dir, "inc.glsl", "float a;\nfloat b\n");
        SourceMap map = process("m.frag", Map.of("D", "1")).sourceMap();
        // preprocessed: 1 #version, 2 #define D, 3 float a; (inc 1), 4 float b (inc 2), 5 // #include, 6 main
        String log = String.join("\n",
                "0:4(1): error: syntax error, unexpected VOID",                     // Mesa
                "0(6) : error C1008: undefined variable \"x\"",                     // NVIDIA
                "ERROR: 0:3: 'a' : redefinition",                                   // AMD / Intel
                "WARNING: 0:2: extension not supported",
                "some other line",
                "");
        assertEquals(List.of(
                "inc.glsl:2: error: syntax error, unexpected VOID",
                "m.frag:3: error C1008: undefined variable \"x\"",
                "inc.glsl:1: error: 'a' : redefinition",
                "<defines>:1: warning: extension not supported",
                "some other line"), ShaderLogTranslator.translate(log, map));
    }
}
