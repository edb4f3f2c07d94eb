package dev.strahl.codec.exr;

/**
 * The Huffman code of PIZ. The block starts with five little-endian uint32: the smallest and the
 * largest symbol of the code table (the largest is the run-length escape), the table's length in
 * bytes, the number of bits of coded data, and 0. Bits are read most significant first.
 *
 * <p><b>Table.</b> For every symbol from the smallest to the largest, a 6-bit code length 0..58
 * (0: the symbol does not occur), except that 59..62 stand for a run of 2..5 absent symbols, and 63
 * followed by 8 bits r for a run of r + 6 absent symbols. The codes are canonical, assigned from the
 * longest length down: the first code of the longest length is 0; the first code of length l is
 * ⌊(first code of length l+1 + number of codes of length l+1) / 2⌋; within a length, symbols take
 * consecutive codes in increasing order.
 *
 * <p><b>Data.</b> A sequence of codes; after the code of the escape symbol, 8 bits give how many
 * more copies of the previous value follow.
 */
final class PizHuffman {
    private static final int MAX_SYMBOL = 1 << 16;       // the escape may be one past the largest 16-bit value
    private static final int MAX_LENGTH = 58;
    static final int TABLE_BITS = 14;
    private static final int LONG = -1;                 // a table entry that starts codes longer than TABLE_BITS

    private PizHuffman() {
    }

    /** Decodes {@code in[off, off + length)} into all of {@code out}. */
    static void decode(byte[] in, int off, int length, char[] out) throws CorruptDataException {
        decode(in, off, length, out, new int[1 << TABLE_BITS]);
    }

    /** As above, with {@code lookup} (2^TABLE_BITS entries, any content) as the room of the decoding table. */
    static void decode(byte[] in, int off, int length, char[] out, int[] lookup) throws CorruptDataException {
        if (length == 0) {
            if (out.length != 0) {
                throw new CorruptDataException("PIZ Huffman data are empty");
            }
            return;
        }
        if (length < 20) {
            throw new CorruptDataException("PIZ Huffman data end inside their 20-byte header");
        }
        long first = u32(in, off);
        long escape = u32(in, off + 4);
        long bits = u32(in, off + 12);
        if (first > MAX_SYMBOL || escape > MAX_SYMBOL || first > escape) {
            throw new CorruptDataException("PIZ Huffman symbol range " + first + ".." + escape + " is invalid");
        }
        BitReader table = new BitReader(in, off + 20, off + length);
        int[] lengths = readLengths(table, (int) first, (int) escape);
        int dataStart = table.nextByte();
        long available = 8L * (off + length - dataStart);
        if (bits > available) {
            throw new CorruptDataException("PIZ Huffman data claim " + bits + " bits, but " + available + " follow");
        }
        long[] codes = canonicalCodes(lengths, (int) first, (int) escape);
        decodeData(new BitReader(in, dataStart, off + length), bits, lengths, codes, (int) first, (int) escape, out, lookup);
    }

    private static long u32(byte[] b, int at) {
        return (b[at] & 0xffL) | (b[at + 1] & 0xffL) << 8 | (b[at + 2] & 0xffL) << 16 | (b[at + 3] & 0xffL) << 24;
    }

    private static int[] readLengths(BitReader r, int first, int last) throws CorruptDataException {
        int[] lengths = new int[last + 1];
        for (int s = first; s <= last; ) {
            int l = (int) r.take(6);
            if (l == 63) {
                s += (int) r.take(8) + 6;
            } else if (l >= 59) {
                s += l - 59 + 2;
            } else {
                lengths[s++] = l;
                continue;
            }
            if (s > last + 1) {
                throw new CorruptDataException("PIZ Huffman table: a run of absent symbols goes past the last symbol");
            }
        }
        return lengths;
    }

    /** The canonical code of each symbol (see the class comment); fails if a code does not fit its length. */
    private static long[] canonicalCodes(int[] lengths, int first, int last) throws CorruptDataException {
        long[] count = new long[MAX_LENGTH + 1];
        for (int s = first; s <= last; s++) {
            count[lengths[s]]++;
        }
        long[] next = new long[MAX_LENGTH + 1];
        long c = 0;
        for (int l = MAX_LENGTH; l > 0; l--) {
            next[l] = c;
            c = (c + count[l]) >> 1;
        }
        long[] codes = new long[last + 1];
        for (int s = first; s <= last; s++) {
            int l = lengths[s];
            if (l > 0) {
                codes[s] = next[l]++;
                if (codes[s] >>> l != 0) {
                    throw new CorruptDataException("PIZ Huffman table: the code lengths do not form a code");
                }
            }
        }
        return codes;
    }

    private static void decodeData(BitReader r, long bits, int[] lengths, long[] codes, int first, int escape, char[] out, int[] table)
            throws CorruptDataException {
        // codes of up to TABLE_BITS bits: one table lookup. Longer ones are found by their length: the
        // codes of one length are consecutive in symbol order (canonical), so a code of length l is
        // the symbol at (code - the length's first code) in that length's list, if that is in range.
        // (A list scan per prefix instead made a hostile table of many long codes cost minutes.)
        java.util.Arrays.fill(table, 0);
        int[] longCount = new int[MAX_LENGTH + 1];
        for (int s = first; s <= escape; s++) {
            int l = lengths[s];
            if (l == 0) {
                continue;
            }
            if (l <= TABLE_BITS) {
                int from = (int) (codes[s] << (TABLE_BITS - l));
                int to = from + (1 << (TABLE_BITS - l));
                for (int i = from; i < to; i++) {
                    if (table[i] != 0) {
                        throw new CorruptDataException("PIZ Huffman table: two codes share a prefix");
                    }
                    table[i] = s << 6 | l;
                }
            } else {
                int prefix = (int) (codes[s] >>> (l - TABLE_BITS));
                if (table[prefix] > 0) {
                    throw new CorruptDataException("PIZ Huffman table: two codes share a prefix");
                }
                table[prefix] = LONG;
                longCount[l]++;
            }
        }
        int[][] longSymbols = new int[MAX_LENGTH + 1][];
        long[] firstLongCode = new long[MAX_LENGTH + 1];
        for (int l = TABLE_BITS + 1; l <= MAX_LENGTH; l++) {
            longSymbols[l] = new int[longCount[l]];
            longCount[l] = 0;
        }
        for (int s = first; s <= escape; s++) {
            int l = lengths[s];
            if (l > TABLE_BITS) {
                if (longCount[l] == 0) {
                    firstLongCode[l] = codes[s];
                }
                longSymbols[l][longCount[l]++] = s;
            }
        }
        int o = 0;
        while (r.position() < bits) {
            long left = bits - r.position();
            int e = table[(int) r.peek(TABLE_BITS)];
            int symbol = -1;
            int l = 0;
            if (e > 0) {
                symbol = e >>> 6;
                l = e & 63;
            } else if (e == LONG) {
                for (int length = TABLE_BITS + 1; length <= MAX_LENGTH && length <= left && symbol < 0; length++) {
                    long k = r.peek(length) - firstLongCode[length];
                    if (k >= 0 && k < longCount[length]) {
                        symbol = longSymbols[length][(int) k];
                        l = length;
                    }
                }
            }
            if (symbol < 0 || l > left) {
                throw new CorruptDataException("PIZ Huffman data: no valid code at bit " + r.position());
            }
            r.skip(l);
            if (symbol == escape) {
                if (left - l < 8) {
                    throw new CorruptDataException("PIZ Huffman data end inside a run length");
                }
                int run = (int) r.take(8);
                if (o == 0) {
                    throw new CorruptDataException("PIZ Huffman data start with a run");
                }
                if (run > out.length - o) {
                    throw new CorruptDataException("PIZ Huffman data decode to more than the chunk's " + out.length + " values");
                }
                java.util.Arrays.fill(out, o, o + run, out[o - 1]);
                o += run;
            } else {
                if (o == out.length) {
                    throw new CorruptDataException("PIZ Huffman data decode to more than the chunk's " + out.length + " values");
                }
                out[o++] = (char) symbol;
            }
        }
        if (o != out.length) {
            throw new CorruptDataException("PIZ Huffman data decode to " + o + " values, the chunk needs " + out.length);
        }
    }

    /** Reads bits most significant first from {@code b[start, end)}; reading past the end gives zeros (peek) or fails (take). */
    static final class BitReader {
        private final byte[] b;
        private final int start;
        private final int end;
        private long position;                // in bits from start

        BitReader(byte[] b, int start, int end) {
            this.b = b;
            this.start = start;
            this.end = end;
        }

        long position() {
            return position;
        }

        /** The byte after the last one any taken bit came from. */
        int nextByte() {
            return start + (int) ((position + 7) >>> 3);
        }

        void skip(int n) {
            position += n;
        }

        /** The next {@code n} ≤ 58 bits, without moving; zeros past the end. */
        long peek(int n) {
            if (n <= 32) {
                return bits(position, n);
            }
            return bits(position, n - 32) << 32 | bits(position + n - 32, 32);
        }

        /** The next {@code n} ≤ 58 bits; fails if they are not all in the data. */
        long take(int n) throws CorruptDataException {
            if (position + n > 8L * (end - start)) {
                throw new CorruptDataException("PIZ Huffman table ends early (at byte " + (end - start) + " of the Huffman data)");
            }
            long v = peek(n);
            position += n;
            return v;
        }

        /** n ≤ 32 bits at bit p: five bytes cover them at any offset within a byte. */
        private long bits(long p, int n) {
            int at = start + (int) (p >>> 3);
            long w = 0;
            for (int i = 0; i < 5; i++) {
                w = w << 8 | (at + i < end ? b[at + i] & 0xff : 0);
            }
            return (w >>> (40 - (int) (p & 7) - n)) & ((1L << n) - 1);
        }
    }
}
