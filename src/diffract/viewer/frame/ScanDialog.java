package diffract.viewer.frame;

import diffract.optics.io.ChannelChoice;
import diffract.optics.io.HeightFieldReader;
import diffract.optics.io.ScanChannel;
import diffract.scene.Scene;
import diffract.util.Reporter;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextField;
import javax.swing.ListSelectionModel;
import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * What opening a height-field file from the frame asks: a .gwy's or .ibw's channel, listed with its unit, samples and
 * extent (the one {@code channels} marks preselected; a channel that holds no heights says so and is not taken), and an
 * image's or a text matrix's sizes (the options {@code --max-height} and {@code --pixel-size} give on the command line).
 * A .gsf says everything itself: no dialog.
 */
final class ScanDialog {
    /** The dialog's name, by which tests find it among the windows. */
    static final String NAME = "diffract-scan-dialog";

    private ScanDialog() {
    }

    /** The file as a scene's patch, after asking what it needs; empty when the user cancels or it cannot be read. */
    static Optional<Scene.FilePatch> ask(JFrame owner, Path file, Reporter reporter) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        try {
            if (name.endsWith(".gwy") || name.endsWith(".ibw")) {
                List<ScanChannel> channels = HeightFieldReader.channels(file, reporter);
                return chooseChannel(owner, file, channels).map(c -> new Scene.FilePatch(file, null, null,
                        Integer.toString(c.index()), null));
            }
            if (name.endsWith(".png") || name.endsWith(".bmp") || name.endsWith(".tif") || name.endsWith(".tiff")) {
                return askSizes(owner, file, true);
            }
            if (name.endsWith(".txt") || name.endsWith(".csv")) {
                return askSizes(owner, file, false);
            }
            return Optional.of(new Scene.FilePatch(file, null, null, null, null));
        } catch (RuntimeException e) {
            ViewerFrame.showError(owner, "cannot read " + file + ": " + e.getMessage());
            return Optional.empty();
        }
    }

    private static Optional<ScanChannel> chooseChannel(JFrame owner, Path file, List<ScanChannel> channels) {
        JDialog dialog = new JDialog(owner, "Channels of " + file.getFileName(), true);
        dialog.setName(NAME);
        JList<String> list = new JList<>(channels.stream().map(ScanDialog::describe).toArray(String[]::new));
        list.setName("channels");
        list.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        ChannelChoice.byDefault(channels).ifPresent(c -> list.setSelectedIndex(channels.indexOf(c)));
        JLabel reason = new JLabel(" ");
        JButton open = new JButton("Open");
        JButton cancel = new JButton("Cancel");
        ScanChannel[] chosen = new ScanChannel[1];
        list.addListSelectionListener(e -> {
            int i = list.getSelectedIndex();
            boolean heights = i >= 0 && channels.get(i).holdsHeights();
            open.setEnabled(heights);
            reason.setText(i < 0 || heights ? " " : "'" + channels.get(i).title() + "' is in "
                    + (channels.get(i).unit().isEmpty() ? "no unit" : channels.get(i).unit())
                    + ", not a length: it holds no heights");
        });
        open.setEnabled(list.getSelectedIndex() >= 0 && channels.get(list.getSelectedIndex()).holdsHeights());
        open.addActionListener(e -> {
            chosen[0] = channels.get(list.getSelectedIndex());
            dialog.dispose();
        });
        cancel.addActionListener(e -> dialog.dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(cancel);
        buttons.add(open);
        JPanel south = new JPanel(new BorderLayout());
        south.add(reason, BorderLayout.CENTER);
        south.add(buttons, BorderLayout.SOUTH);
        JPanel content = new JPanel(new BorderLayout(4, 4));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        content.add(new JLabel("the channel to read as the height field:"), BorderLayout.NORTH);
        content.add(new JScrollPane(list), BorderLayout.CENTER);
        content.add(south, BorderLayout.SOUTH);
        dialog.setContentPane(content);
        dialog.getRootPane().setDefaultButton(open);
        dialog.pack();
        dialog.setLocationRelativeTo(owner);
        dialog.setVisible(true); // modal: returns when closed
        return Optional.ofNullable(chosen[0]);
    }

    /** "1 'Height' in m, 256 x 256 samples, 5.0 x 5.0 um" (extent in um where the unit is a length). */
    static String describe(ScanChannel c) {
        double w = c.widthUm();
        double h = c.heightExtentUm();
        String extent = Double.isFinite(w) && Double.isFinite(h) ? String.format(Locale.ROOT, ", %.3g x %.3g um", w, h)
                : "";
        return String.format(Locale.ROOT, "%d '%s' in %s, %d x %d samples%s%s", c.index(), c.title(),
                c.unit().isEmpty() ? "no unit" : c.unit(), c.cols(), c.rows(), extent,
                c.holdsHeights() ? "" : " (no heights)");
    }

    private static Optional<Scene.FilePatch> askSizes(JFrame owner, Path file, boolean image) {
        JDialog dialog = new JDialog(owner, "Sizes of " + file.getFileName(), true);
        dialog.setName(NAME);
        JTextField maxHeight = new JTextField(8);
        maxHeight.setName("maxHeight");
        JTextField pixelSize = new JTextField(8);
        pixelSize.setName("pixelSize");
        JLabel reason = new JLabel(" ");
        JPanel fields = new JPanel(new GridLayout(0, 2, 4, 4));
        if (image) {
            fields.add(new JLabel("height of the brightest grey (um)"));
            fields.add(maxHeight);
        }
        fields.add(new JLabel("pixel size (um)"));
        fields.add(pixelSize);
        Scene.FilePatch[] chosen = new Scene.FilePatch[1];
        JButton open = new JButton("Open");
        JButton cancel = new JButton("Cancel");
        open.addActionListener(e -> {
            try {
                Double height = image ? positive(maxHeight.getText(), "the height") : null;
                double pixel = positive(pixelSize.getText(), "the pixel size");
                chosen[0] = new Scene.FilePatch(file, height, pixel, null, null);
                dialog.dispose();
            } catch (IllegalArgumentException ex) {
                reason.setText(ex.getMessage());
            }
        });
        cancel.addActionListener(e -> dialog.dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(cancel);
        buttons.add(open);
        JPanel content = new JPanel(new BorderLayout(4, 4));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        content.add(fields, BorderLayout.NORTH);
        content.add(reason, BorderLayout.CENTER);
        content.add(buttons, BorderLayout.SOUTH);
        dialog.setContentPane(content);
        dialog.getRootPane().setDefaultButton(open);
        dialog.pack();
        dialog.setLocationRelativeTo(owner);
        dialog.setVisible(true);
        return Optional.ofNullable(chosen[0]);
    }

    private static double positive(String text, String what) {
        try {
            double v = Double.parseDouble(text.strip());
            if (v > 0 && Double.isFinite(v)) {
                return v;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new IllegalArgumentException(what + " must be a positive number of micrometres, got '" + text + "'");
    }
}
