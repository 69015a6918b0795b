package diffract.precompute;

import diffract.util.TestReport;
import diffract.app.Main;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.io.GsfWriter;
import diffract.optics.io.HeightFieldReader;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** (c) A thesis-format folder renders the same BRDF map as the native one; and the CLI path through both. */
class ThesisRenderTest {
    @TempDir
    Path tmp;

    /**
     * FLSS with the thesis' settings (30 terms, 3 x 3 window, 5 nm) on a blazed grating of even height (the row
     * shift of ThesisLayout matters). The terms differ by the normalisation's rounding only (a fraction of an
     * ulp of float32 relative to each term's range, see ThesisFormatTest), so the maps agree to a few 1e-7 of
     * their peak (measured: 5e-9); we allow 1e-6.
     */
    @Test
    void thesisFolderRendersTheSameMapAsTheNativeFolder() throws IOException {
        HeightField field = SyntheticPatches.blazed(2.5, 0.2, 10, 4, 10).meanSubtracted();
        BrdfSettings settings = BrdfSettings.thesis(Variant.FLSS);
        TaylorTerms terms = TaylorTermComputer.compute(field, settings.taylor().highestOrder(), Reporter.SILENT);
        Path nativeDir = tmp.resolve("native");
        TermStore.write(nativeDir, terms, new TermSidecar.Patch("blazed", field.contentSha256(), field.rows(),
                field.cols(), field.pixelSizeXUm(), field.pixelSizeYUm(), null, field.maxAbsHeightUm()),
                Precomputation.select(new Precomputation.Request(field, "blazed", null, 30, null, 380), Reporter.SILENT),
                "test");
        Path thesisDir = tmp.resolve("thesis");
        ThesisFormat.write(thesisDir, terms, new ThesisFormat.Provenance("blazed", field.contentSha256(), null),
                Reporter.SILENT);
        Path scriptDir = tmp.resolve("script"); // as the original script leaves it: no diffract.json
        ThesisFormat.write(scriptDir, terms, new ThesisFormat.Provenance("blazed", null, null), Reporter.SILENT);
        Files.delete(scriptDir.resolve(ThesisFormat.EXTRAS_FILE));

        Direction wi = Direction.fromSphericalDeg(30, 0);
        DiffractionBrdf reference = DiffractionBrdf.create(settings, field, TermFolders.read(nativeDir, Reporter.SILENT));
        float[] xyzNative = BrdfMap.xyz(reference, wi, 32, Reporter.SILENT);
        float[] greyNative = BrdfMap.monochromatic(reference, wi, 550, 32, Reporter.SILENT);
        for (Path dir : new Path[] {thesisDir, scriptDir}) {
            DiffractionBrdf brdf = DiffractionBrdf.create(settings, field, TermFolders.read(dir, Reporter.SILENT));
            double xyz = relativeDifference(xyzNative, BrdfMap.xyz(brdf, wi, 32, Reporter.SILENT));
            double grey = relativeDifference(greyNative, BrdfMap.monochromatic(brdf, wi, 550, 32, Reporter.SILENT));
            TestReport.printf(ThesisRenderTest.class, Locale.ROOT, "thesis render %s: max |difference| / peak: XYZ %.3g, 550 nm %.3g%n",
                    dir.getFileName(), xyz, grey);
            assertTrue(xyz < 1e-6, "XYZ map differs by " + xyz + " of its peak");
            assertTrue(grey < 1e-6, "550 nm map differs by " + grey + " of its peak");
        }
    }

    @Test
    void precomputeThesisFormatConvertAndRenderFromTheCommandLine() throws IOException {
        HeightField field = SyntheticPatches.sinusoid(2.5, 0.2, 8, 3, 5);
        Path patch = tmp.resolve("p.gsf");
        GsfWriter.write(patch, field);
        Path thesis = tmp.resolve("thesis");
        assertEquals(0, Main.execute("precompute", "--patch", patch.toString(), "--terms", "6", "--format", "thesis",
                "-o", thesis.toString()));
        assertTrue(Files.isRegularFile(thesis.resolve("AmpReIm6.txt")));
        assertEquals(0, Main.execute("precompute", "--patch", patch.toString(), "--terms", "6", "--format", "thesis",
                "-o", thesis.toString())); // reused
        Path nativeDir = tmp.resolve("native");
        assertEquals(0, Main.execute("convert-terms", "--from", thesis.toString(), "--to", nativeDir.toString()));
        Path back = tmp.resolve("back");
        assertEquals(0, Main.execute("convert-terms", "--from", nativeDir.toString(), "--to", back.toString(),
                "--format", "thesis"));
        // the field as precompute reads it by default (the format's levelling)
        HeightField levelled = HeightFieldReader.load(patch, null, null, null, null, Reporter.SILENT);
        TaylorTerms direct = TaylorTermComputer.compute(levelled, 6, Reporter.SILENT);
        for (Path dir : new Path[] {thesis, nativeDir, back}) {
            TaylorTerms read = TermFolders.read(dir, Reporter.SILENT);
            for (int n = 0; n <= 6; n++) {
                double scale = ThesisFormatTest.maxAbs(direct.termData(n));
                float[] want = direct.termData(n);
                float[] got = read.termData(n);
                for (int i = 0; i < got.length; i++) {
                    assertEquals(want[i], got[i], 1e-6 * scale, dir.getFileName() + " term " + n);
                }
            }
        }
        Path map = tmp.resolve("map.png");
        assertEquals(0, Main.execute("brdfmap", "--patch", patch.toString(), "--theta-i", "20", "--variant", "flss",
                "--terms", "6", "--terms-dir", thesis.toString(), "--size", "8", "--lambda", "500", "-o", map.toString()));
        assertTrue(Files.size(map) > 0);
        assertEquals(2, Main.execute("convert-terms", "--from", tmp.resolve("nowhere").toString(), "--to",
                tmp.resolve("x").toString()));
    }

    private static double relativeDifference(float[] a, float[] b) {
        double peak = 0;
        double worst = 0;
        for (int i = 0; i < a.length; i++) {
            peak = Math.max(peak, Math.abs(a[i]));
            worst = Math.max(worst, Math.abs(a[i] - b[i]));
        }
        assertTrue(peak > 0, "the map is not black");
        return worst / peak;
    }
}
