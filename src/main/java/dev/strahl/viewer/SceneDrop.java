package dev.strahl.viewer;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.File;
import java.io.IOException;
import java.net.URI;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.TransferHandler;

/**
 * A file dropped onto the window opens as the scene: whatever its format, it goes to the scene
 * loader ({@link FileActions#openScene}), which reads .json, .obj and .ply (and whatever it learns
 * to read) and refuses anything else with a one-line message in a dialog. Of several files dropped
 * at once the first opens. Takes Java's file lists and the {@code text/uri-list} that some X11
 * file managers offer instead.
 */
final class SceneDrop extends TransferHandler {
    static final DataFlavor URI_LIST = uriList();

    private final Consumer<Path> open;

    SceneDrop(Consumer<Path> open) {
        this.open = open;
    }

    private static DataFlavor uriList() {
        try {
            return new DataFlavor("text/uri-list;class=java.lang.String");
        } catch (ClassNotFoundException e) {
            throw new IllegalStateException(e);       // java.lang.String is always there
        }
    }

    @Override
    public boolean canImport(TransferSupport support) {
        return support.isDataFlavorSupported(DataFlavor.javaFileListFlavor) || support.isDataFlavorSupported(URI_LIST);
    }

    @Override
    public boolean importData(TransferSupport support) {
        if (!canImport(support)) {
            return false;
        }
        Path file = firstFile(support.getTransferable());
        if (file == null) {
            return false;
        }
        open.accept(file);
        return true;
    }

    /** The first file of the transfer, or null if it holds none. */
    static Path firstFile(Transferable t) {
        try {
            if (t.isDataFlavorSupported(DataFlavor.javaFileListFlavor)) {
                List<?> files = (List<?>) t.getTransferData(DataFlavor.javaFileListFlavor);
                return files.isEmpty() ? null : ((File) files.get(0)).toPath();
            }
            if (t.isDataFlavorSupported(URI_LIST)) {
                for (String line : ((String) t.getTransferData(URI_LIST)).split("\r?\n")) {
                    String s = line.trim();
                    if (s.startsWith("file:")) {
                        return Path.of(URI.create(s));
                    }
                }
            }
        } catch (UnsupportedFlavorException | IOException | IllegalArgumentException e) {
            return null;                               // a transfer that changed its mind, or a URI that is no file
        }
        return null;
    }
}
