package diffract.optics;

/**
 * Rows {@code fromRow} (inclusive) to {@code toRow} (exclusive) of a BRDF map: the piece of the map one process
 * computes when the work is split. Band {@code index} of {@code count} is fixed by the map size alone, so every
 * process that is handed the same piece computes the same rows.
 */
public record MapBand(int fromRow, int toRow) {
    public MapBand {
        if (fromRow < 0 || toRow <= fromRow) {
            throw new IllegalArgumentException("a band needs rows, got " + fromRow + ".." + toRow);
        }
    }

    /** Band {@code index} (0-based) of {@code count} contiguous bands of a {@code sizePx}-row map, as even as rows allow. */
    public static MapBand of(int index, int count, int sizePx) {
        if (count < 1 || count > sizePx || index < 0 || index >= count) {
            throw new IllegalArgumentException("band " + index + " of " + count + " of " + sizePx + " rows");
        }
        // long products: 8192 rows times 8192 bands stays exact
        return new MapBand((int) ((long) index * sizePx / count), (int) ((long) (index + 1) * sizePx / count));
    }

    public int rows() {
        return toRow - fromRow;
    }

    /** The band in a progress line: empty for the whole map. */
    String label(int sizePx) {
        return fromRow == 0 && toRow == sizePx ? "" : ", rows " + this;
    }

    @Override
    public String toString() {
        return fromRow + ".." + (toRow - 1);
    }
}
