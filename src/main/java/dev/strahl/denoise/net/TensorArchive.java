package dev.strahl.denoise.net;

import dev.strahl.codec.Printable;
import dev.strahl.codec.exr.Half;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A tensor archive (.tza), the weight format of Intel Open Image Denoise: little endian; magic
 * {@code 0x41D7}, major version 2, minor version, the offset of the tensor table (uint64); the
 * table holds a count (uint32) and per tensor its name (uint16 length + ASCII), rank (uint8),
 * dimensions (uint32 each), layout (one letter per dimension, {@code x} or {@code oihw}), type
 * ({@code f} float32 or {@code h} float16) and the offset of its data (uint64). Tensors are read
 * into float arrays (halves converted exactly).
 *
 * <p>A damaged file is refused with one line naming it, the tensor and what is wrong (a name from
 * the file quoted printably and cut short, as {@link Printable} does); nothing is allocated before
 * the bytes it describes are known to be there: a tensor's size is checked against the file before
 * its array is made, and all tensors together may claim no more bytes than the file has (in a real
 * archive they do not overlap), so a small hostile file cannot make the reader allocate much more
 * than twice its own size.
 */
final class TensorArchive {
    static final int MAGIC = 0x41D7;
    static final int MAJOR_VERSION = 2;

    /** One tensor: its dimensions (outermost first, in its layout's order) and its values. */
    record Tensor(String name, int[] dims, String layout, float[] data) {
        int dim(int i) {
            return dims[i];
        }
    }

    private final String source;
    private final Map<String, Tensor> tensors;

    private TensorArchive(String source, Map<String, Tensor> tensors) {
        this.source = source;
        this.tensors = Collections.unmodifiableMap(tensors);
    }

    /** The tensors by name, in the file's order. */
    Map<String, Tensor> tensors() {
        return tensors;
    }

    /**
     * The named tensor with the given dimensions.
     *
     * @throws TensorArchiveException if it is missing or has other dimensions
     */
    Tensor tensor(String name, int... dims) throws TensorArchiveException {
        Tensor t = tensors.get(name);
        if (t == null) {
            throw new TensorArchiveException(source + ": no tensor '" + name + "'");
        }
        if (!java.util.Arrays.equals(t.dims(), dims)) {
            throw new TensorArchiveException(source + ": tensor '" + name + "' has dimensions " + java.util.Arrays.toString(t.dims())
                    + ", expected " + java.util.Arrays.toString(dims));
        }
        return t;
    }

    /**
     * Parses an archive.
     *
     * @param source what to call it in messages (a file or resource name)
     * @param bytes  the whole file
     * @throws TensorArchiveException if it is not a version 2 archive or is damaged or truncated
     */
    static TensorArchive read(String source, byte[] bytes) throws TensorArchiveException {
        return new Parser(source, bytes).parse();
    }

    /** The one-pass reader; every read is bounds-checked against the file. */
    private static final class Parser {
        private final String source;
        private final ByteBuffer buf;
        /** Data bytes of the tensors read so far. */
        private long claimed;

        Parser(String source, byte[] bytes) {
            this.source = source;
            this.buf = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        }

        TensorArchive parse() throws TensorArchiveException {
            need(0, 12, "the header");
            int magic = buf.getShort(0) & 0xffff;
            if (magic != MAGIC) {
                throw fail(String.format("not a tensor archive (magic 0x%04X, expected 0x%04X)", magic, MAGIC));
            }
            int major = buf.get(2) & 0xff;
            if (major != MAJOR_VERSION) {
                throw fail("format version " + major + "." + (buf.get(3) & 0xff) + ", only version 2 is supported");
            }
            long table = offset(buf.getLong(4), "the tensor table");
            need(table, 4, "the tensor count");
            long count = buf.getInt((int) table) & 0xffffffffL;
            long minEntry = 2 + 1 + 1 + 8;                      // empty name, rank 0, type, offset
            if (count > (buf.capacity() - table - 4) / minEntry) {
                throw fail("the table claims " + count + " tensors, more than its " + (buf.capacity() - table - 4) + " bytes can hold");
            }
            Map<String, Tensor> tensors = new LinkedHashMap<>();
            claimed = 0;
            int p = (int) table + 4;
            for (long i = 0; i < count; i++) {
                p = entry(p, i, tensors);
            }
            return new TensorArchive(source, tensors);
        }

        /** Reads the table entry at {@code p} and its tensor; returns where the next entry starts. */
        private int entry(int p, long index, Map<String, Tensor> tensors) throws TensorArchiveException {
            String what = "the entry of tensor " + index;
            need(p, 2, what);
            int nameLength = buf.getShort(p) & 0xffff;
            need(p + 2L, nameLength + 1L, what);
            byte[] nameBytes = new byte[nameLength];
            buf.get(p + 2, nameBytes);
            String name = new String(nameBytes, StandardCharsets.US_ASCII);
            String quoted = Printable.quote(name);
            what = "the entry of tensor " + quoted;
            p += 2 + nameLength;
            int rank = buf.get(p) & 0xff;
            p++;
            need(p, 4L * rank + rank + 1 + 8, what);
            int[] dims = new int[rank];
            long elements = 1;
            for (int d = 0; d < rank; d++) {
                long dim = buf.getInt(p + 4 * d) & 0xffffffffL;
                if (dim > Integer.MAX_VALUE) {
                    throw fail("tensor " + quoted + " has dimension " + dim);
                }
                dims[d] = (int) dim;
                elements = dim == 0 || elements <= Long.MAX_VALUE / 16 / dim ? elements * dim : Long.MAX_VALUE / 16;
            }
            p += 4 * rank;
            byte[] layoutBytes = new byte[rank];
            buf.get(p, layoutBytes);
            String layout = new String(layoutBytes, StandardCharsets.US_ASCII);
            p += rank;
            if (!layout.equals("x") && !layout.equals("oihw")) {
                throw fail("tensor " + quoted + " has layout " + Printable.quote(layout) + " (expected x or oihw)");
            }
            char type = (char) (buf.get(p) & 0xff);
            int size = type == 'f' ? 4 : type == 'h' ? 2 : 0;
            if (size == 0) {
                throw fail("tensor " + quoted + " has data type " + Printable.quote(String.valueOf(type)) + " (expected f or h)");
            }
            long data = offset(buf.getLong(p + 1), "the data of tensor " + quoted);
            p += 9;
            long bytes = elements * size;
            if (bytes > buf.capacity() - data) {
                throw fail("truncated: tensor " + quoted + " " + java.util.Arrays.toString(dims) + " needs " + bytes + " bytes at offset "
                        + data + ", the file has " + buf.capacity());
            }
            claimed += bytes;
            if (claimed > buf.capacity()) {
                throw fail("tensor " + quoted + " makes the tensors' data " + claimed + " bytes, more than the file's " + buf.capacity()
                        + " (tensors overlap)");
            }
            if (tensors.containsKey(name)) {
                throw fail("tensor " + quoted + " appears twice");
            }
            tensors.put(name, new Tensor(name, dims, layout, values((int) data, (int) elements, type)));
            return p;
        }

        private float[] values(int at, int n, char type) {
            float[] v = new float[n];
            for (int i = 0; i < n; i++) {
                v[i] = type == 'f' ? buf.getFloat(at + 4 * i) : Half.toFloat(buf.getShort(at + 2 * i) & 0xffff);
            }
            return v;
        }

        private long offset(long value, String what) throws TensorArchiveException {
            if (value < 0 || value > buf.capacity()) {
                throw fail("truncated: " + what + " is at offset " + Long.toUnsignedString(value) + ", the file has " + buf.capacity() + " bytes");
            }
            return value;
        }

        private void need(long at, long n, String what) throws TensorArchiveException {
            if (at + n > buf.capacity()) {
                throw fail("truncated: " + what + " needs bytes " + at + ".." + (at + n) + ", the file has " + buf.capacity());
            }
        }

        private TensorArchiveException fail(String what) {
            return new TensorArchiveException(Printable.path(source) + ": " + what);
        }
    }
}
