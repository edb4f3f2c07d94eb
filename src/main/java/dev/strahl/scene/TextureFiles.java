package dev.strahl.scene;

import dev.strahl.codec.ChannelImage;
import dev.strahl.files.FileReads;
import dev.strahl.codec.TextureImages;
import dev.strahl.texture.Bitmap;
import java.io.IOException;
import java.lang.ref.WeakReference;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.HashMap;
import java.util.Map;

/**
 * The texture images loaded so far, by file: a file that many materials use (or many scenes of one
 * JVM, such as the viewer's) is read and stored once, for as long as some texture holds it. Keyed
 * by the real path with the file's size and modification time, so an edited file is read again.
 */
final class TextureFiles {
    private record Key(Path realPath, long size, long modified) {}

    private static final Map<Key, WeakReference<Bitmap>> CACHE = new HashMap<>();

    private TextureFiles() {}

    /** The pixels of a PNG or JPEG file, as stored (no sRGB decoding), bottom row first. */
    static Bitmap load(Path file) throws IOException {
        Path real = file.toRealPath();
        BasicFileAttributes attributes = Files.readAttributes(real, BasicFileAttributes.class);
        Key key = new Key(real, attributes.size(), attributes.lastModifiedTime().toMillis());
        synchronized (CACHE) {
            WeakReference<Bitmap> ref = CACHE.get(key);
            Bitmap cached = ref == null ? null : ref.get();
            if (cached != null) {
                FileReads.note(file);        // read once, but still a file of this scene (a cluster ships what is noted)
                return cached;
            }
        }
        ChannelImage image = TextureImages.read(file);
        Bitmap bitmap = Bitmap.fromTopDown(file.getFileName().toString(), image.width(), image.height(), image.channelCount(), image.data());
        synchronized (CACHE) {
            CACHE.values().removeIf(r -> r.get() == null);
            WeakReference<Bitmap> ref = CACHE.get(key);
            Bitmap raced = ref == null ? null : ref.get();
            if (raced != null) {
                return raced;
            }
            CACHE.put(key, new WeakReference<>(bitmap));
        }
        return bitmap;
    }
}
