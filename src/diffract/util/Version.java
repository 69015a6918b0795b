package diffract.util;

/** The program's version, recorded in every file it writes so that a later reader knows what produced it. */
public final class Version {
    /** Keep in step with pom.xml's {@code <version>}. */
    public static final String VERSION = "0.1.0";

    private Version() {
    }
}
