package diffract.optics.io;

import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.util.Reporter;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Collectors;

import static diffract.optics.io.ReaderSupport.printable;

/**
 * Which channel of a multi-channel AFM file is the height field. By default the first one in a length unit, where
 * one whose title begins with "Height" comes first (an Asylum scan's amplitude and deflection are lengths too); else
 * the channel named by its title (exact, then ignoring case) or by its index. A refusal lists every channel.
 */
public final class ChannelChoice {
    private ChannelChoice() {
    }

    /** The channel read when none is named: empty when no channel holds heights. */
    public static Optional<ScanChannel> byDefault(List<ScanChannel> channels) {
        Optional<ScanChannel> height = channels.stream()
                .filter(c -> c.holdsHeights() && c.title().toLowerCase(Locale.ROOT).startsWith("height"))
                .findFirst();
        return height.isPresent() ? height : channels.stream().filter(ScanChannel::holdsHeights).findFirst();
    }

    /** "0 'Height' (m, 256 x 256), 1 'Phase' (deg, 256 x 256)". */
    static String listing(List<ScanChannel> channels) {
        return channels.stream().map(ScanChannel::summary).collect(Collectors.joining(", "));
    }

    /**
     * @param requested a title or an index, or null for {@link #byDefault}
     * @throws InvalidSettingException (the channel) when nothing fits, listing the channels
     */
    static ScanChannel choose(Path file, List<ScanChannel> channels, String requested, Reporter reporter) {
        String all = "channels: " + listing(channels);
        ScanChannel chosen;
        if (requested == null) {
            chosen = byDefault(channels).orElseThrow(() -> new InvalidSettingException(Quantity.CHANNEL, file
                    + ": no channel holds heights (values in a length unit such as m); " + all + "; save the"
                    + " topography channel with its unit from the microscope's software or Gwyddion"));
        } else {
            chosen = named(file, channels, requested.strip(), all);
            if (!chosen.holdsHeights()) {
                throw new InvalidSettingException(Quantity.CHANNEL, file + ": channel " + chosen.index() + " '"
                        + chosen.title() + "' is in " + (chosen.unit().isEmpty() ? "no unit" : chosen.unit())
                        + ", not a length, so it holds no heights; " + all + "; choose one in a length unit");
            }
        }
        if (channels.size() > 1) {
            reporter.info(file + ": channel " + chosen.summary() + ", one of " + channels.size()
                    + (requested == null ? " (the first that holds heights)" : ""));
        }
        return chosen;
    }

    private static ScanChannel named(Path file, List<ScanChannel> channels, String requested, String all) {
        if (requested.matches("\\d{1,9}")) {
            int index = Integer.parseInt(requested);
            return channels.stream().filter(c -> c.index() == index).findFirst().orElseThrow(() ->
                    new InvalidSettingException(Quantity.CHANNEL, file + ": no channel " + index + "; " + all
                            + "; give a title or an index of these"));
        }
        List<ScanChannel> matches = new ArrayList<>();
        for (ScanChannel c : channels) {
            if (c.title().equals(requested)) {
                matches.add(c);
            }
        }
        if (matches.isEmpty()) {
            for (ScanChannel c : channels) {
                if (c.title().equalsIgnoreCase(requested)) {
                    matches.add(c);
                }
            }
        }
        if (matches.isEmpty()) {
            throw new InvalidSettingException(Quantity.CHANNEL, file + ": no channel '" + printable(requested)
                    + "'; " + all + "; give a title or an index of these");
        }
        if (matches.size() > 1) {
            throw new InvalidSettingException(Quantity.CHANNEL, file + ": " + matches.size() + " channels are titled '"
                    + printable(requested) + "' (" + matches.stream().map(c -> Integer.toString(c.index()))
                    .collect(Collectors.joining(", ")) + "); give the index of the one you mean; " + all);
        }
        return matches.get(0);
    }
}
