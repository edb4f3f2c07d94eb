package dev.strahl.viewer;

import dev.strahl.image.ToneMapping;
import java.awt.event.KeyEvent;
import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JRadioButtonMenuItem;

/**
 * View → Tone mapping: the display's tone curve, one of {@link ToneMapping} (clamp, the default,
 * ACES and AgX: the curves of {@code strahl render --tonemap} for PNGs), applied after the
 * exposure. Display only: it re-converts the last frame and never restarts rendering.
 */
final class ToneMenu {
    private ToneMenu() {}

    /** The menu, its items radio buttons that set {@code presenter}'s curve. */
    static JMenu menu(FramePresenter presenter) {
        JMenu menu = new JMenu("Tone mapping");
        menu.setMnemonic(KeyEvent.VK_T);
        menu.setToolTipText("The display's tone curve after the exposure (display only, keeps rendering)");
        ButtonGroup group = new ButtonGroup();
        for (ToneMapping curve : ToneMapping.values()) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(label(curve), curve == presenter.toneMapping());
            item.addActionListener(e -> presenter.setToneMapping(curve));
            group.add(item);
            menu.add(item);
        }
        return menu;
    }

    /** "Clamp", "ACES", "AgX". */
    static String label(ToneMapping curve) {
        return switch (curve) {
            case CLAMP -> "Clamp";
            case ACES -> "ACES";
            case AGX -> "AgX";
        };
    }
}
