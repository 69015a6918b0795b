package diffract.app;

import diffract.app.options.QuietOption;
import diffract.optics.io.ChannelChoice;
import diffract.optics.io.HeightFieldReader;
import diffract.optics.io.ScanChannel;
import diffract.optics.io.ScanFormat;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;

/** {@code diffract channels FILE}: what a scan file holds, and which channel {@code --patch} reads from it. */
@Command(name = "channels", mixinStandardHelpOptions = true)
final class ChannelsCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", descriptionKey = "scan-file") Path file;

    @Mixin QuietOption quiet;

    @Override
    public Integer call() {
        ScanFormat format = HeightFieldReader.formatOf(file);
        List<ScanChannel> channels = HeightFieldReader.channels(file, quiet.reporter());
        if (channels.isEmpty()) {
            System.out.println(file + ": " + format.words() + ", one height field, no channels (only the"
                    + " instruments' files have them)");
            return 0;
        }
        Optional<ScanChannel> chosen = ChannelChoice.byDefault(channels);
        System.out.println(file + ": " + format.words() + ", " + channels.size()
                + (channels.size() == 1 ? " channel" : " channels")
                + (chosen.isPresent() ? "" : "; none holds heights (a length unit such as m)"));
        for (ScanChannel c : channels) {
            String extent = Double.isNaN(c.widthUm()) ? "" : String.format(Locale.ROOT, ", %s x %s um",
                    number(c.widthUm()), number(c.heightExtentUm()));
            System.out.println((chosen.isPresent() && chosen.get() == c ? "* " : "  ") + c.summary() + extent);
        }
        return 0;
    }

    private static String number(double value) {
        return new java.math.BigDecimal(value).round(new java.math.MathContext(4)).stripTrailingZeros()
                .toPlainString();
    }
}
