package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import java.awt.datatransfer.Transferable;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.prefs.Preferences;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.TransferHandler;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** File → Open Recent's list in java.util.prefs, and a file dropped onto the window. Headless. */
class RecentFilesAndDropTest {
    private final Preferences node = Preferences.userRoot().node("dev/strahl/test/recent-" + System.nanoTime());

    @TempDir
    Path dir;

    @AfterEach
    void removeNode() throws Exception {
        node.removeNode();
    }

    @Test
    void newestFirstWithoutDuplicatesAtMostEight() {
        RecentFiles recent = new RecentFiles(node);
        assertThat(recent.list()).isEmpty();
        for (int i = 0; i < 10; i++) {
            recent.add(dir.resolve("s" + i + ".json"));
        }
        List<Path> expected = new ArrayList<>();
        for (int i = 9; i >= 2; i--) {
            expected.add(dir.resolve("s" + i + ".json").toAbsolutePath());
        }
        assertThat(recent.list()).containsExactlyElementsOf(expected);
        recent.add(dir.resolve("s5.json"));
        assertThat(recent.list()).hasSize(RecentFiles.MAX).first().isEqualTo(dir.resolve("s5.json").toAbsolutePath());
        assertThat(recent.list()).doesNotHaveDuplicates();
        recent.add(dir.resolve("sub/../s5.json"));
        assertThat(recent.list()).as("the same file by another path is one entry").doesNotHaveDuplicates().hasSize(RecentFiles.MAX);
    }

    @Test
    void theListOutlivesTheSessionAndCanBeCleared() {
        new RecentFiles(node).add(Path.of("relative.obj"));
        RecentFiles later = new RecentFiles(node);
        assertThat(later.list()).containsExactly(Path.of("relative.obj").toAbsolutePath());
        later.remove(Path.of("relative.obj"));
        assertThat(later.list()).isEmpty();
        later.add(Path.of("a.ply"));
        later.clear();
        assertThat(new RecentFiles(node).list()).isEmpty();
    }

    @Test
    void theMenuListsTheFilesNewestFirstAndOpensThem() {
        RecentFiles recent = new RecentFiles(node);
        recent.add(dir.resolve("a.json"));
        recent.add(dir.resolve("b.obj"));
        FileActions files = new FileActions(null, new FramePresenter(), s -> { }, null, f -> null, o -> { }, recent);
        JMenu menu = files.recentMenu();
        assertThat(menu.getItem(0).getText()).isEqualTo("1  b.obj");
        assertThat(menu.getItem(1).getText()).isEqualTo("2  a.json");
        assertThat(menu.getItem(3).getText()).isEqualTo("Clear Recent");
        menu.getItem(3).doClick();
        files.fillRecent(menu);
        assertThat(menu.getItem(0).getText()).isEqualTo("No recent scenes");
        assertThat(menu.getItem(0).isEnabled()).isFalse();
    }

    @Test
    void aDroppedFileOfAnyKindGoesToTheLoader() {
        List<Path> opened = new ArrayList<>();
        SceneDrop drop = new SceneDrop(opened::add);
        for (String name : new String[] {"a.json", "b.OBJ", "c.ply", "d.gltf", "e.glb", "f.txt"}) {
            File f = dir.resolve(name).toFile();
            assertThat(drop.importData(new TransferHandler.TransferSupport(new JLabel(), files(f, dir.resolve("second.json").toFile()))))
                    .isTrue();
        }
        assertThat(opened).extracting(p -> p.getFileName().toString()).containsExactly("a.json", "b.OBJ", "c.ply", "d.gltf", "e.glb", "f.txt");
    }

    @Test
    void aUriListFromAnX11FileManagerIsAFileToo() throws Exception {
        List<Path> opened = new ArrayList<>();
        SceneDrop drop = new SceneDrop(opened::add);
        Path file = dir.resolve("with space.json");
        Transferable uris = new Transferable() {
            @Override
            public DataFlavor[] getTransferDataFlavors() {
                return new DataFlavor[] {SceneDrop.URI_LIST};
            }

            @Override
            public boolean isDataFlavorSupported(DataFlavor flavor) {
                return flavor.equals(SceneDrop.URI_LIST);
            }

            @Override
            public Object getTransferData(DataFlavor flavor) {
                return "# a comment\r\n" + file.toUri() + "\r\n";
            }
        };
        assertThat(drop.importData(new TransferHandler.TransferSupport(new JLabel(), uris))).isTrue();
        assertThat(opened).containsExactly(file);
    }

    @Test
    void textIsNoFile() {
        List<Path> opened = new ArrayList<>();
        SceneDrop drop = new SceneDrop(opened::add);
        assertThat(drop.importData(new TransferHandler.TransferSupport(new JLabel(), new StringSelection("scenes/x.json")))).isFalse();
        assertThat(opened).isEmpty();
    }

    private static Transferable files(File... files) {
        return new Transferable() {
            @Override
            public DataFlavor[] getTransferDataFlavors() {
                return new DataFlavor[] {DataFlavor.javaFileListFlavor};
            }

            @Override
            public boolean isDataFlavorSupported(DataFlavor flavor) {
                return flavor.equals(DataFlavor.javaFileListFlavor);
            }

            @Override
            public Object getTransferData(DataFlavor flavor) {
                return List.of(files);
            }
        };
    }
}
