package diffract.jrtr.shaders;

/** A shader's text after define injection and include expansion, with the map back to the original files. */
public record PreprocessedSource(String path, String text, SourceMap sourceMap) {
}
