package dev.strahl.viewer;

import java.awt.Component;
import java.awt.event.ActionEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Function;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JComboBox;
import javax.swing.JList;
import javax.swing.JMenu;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;

/**
 * One setting chosen from a short list (integrator, max depth, sampling, stop-at), shown both as
 * a toolbar combo box and as a menu of radio items, kept in step, with an action that cycles
 * through the values by keyboard. Used on the event dispatch thread only.
 */
final class Choice<T> {
    private final List<T> values;
    private final Function<T, String> label;
    private final Consumer<T> onChange;
    private final List<Runnable> views = new ArrayList<>();
    private T value;

    Choice(List<T> values, T initial, Function<T, String> label, Consumer<T> onChange) {
        if (!values.contains(initial)) {
            throw new IllegalArgumentException(initial + " is not one of " + values);
        }
        this.values = List.copyOf(values);
        this.value = initial;
        this.label = label;
        this.onChange = onChange;
    }

    T value() {
        return value;
    }

    /** Selects {@code v}, updates every view and tells the listener if it changed. */
    void set(T v) {
        if (!values.contains(v)) {
            throw new IllegalArgumentException(v + " is not one of " + values);
        }
        if (v.equals(value)) {
            return;
        }
        value = v;
        views.forEach(Runnable::run);
        onChange.accept(v);
    }

    /** A combo box for the toolbar; {@code prefix} goes before each value ("depth ∞"). */
    JComboBox<T> comboBox(String prefix, String tooltip) {
        JComboBox<T> box = new JComboBox<>(new java.util.Vector<>(values));
        box.setSelectedItem(value);
        box.setToolTipText(tooltip);
        box.setFocusable(false);             // keeps the keyboard shortcuts with the window
        box.setRenderer(new DefaultListCellRenderer() {
            @Override
            public Component getListCellRendererComponent(JList<?> list, Object v, int index, boolean selected, boolean focus) {
                @SuppressWarnings("unchecked")
                String text = (index < 0 ? prefix : "") + label.apply((T) v);
                return super.getListCellRendererComponent(list, text, index, selected, focus);
            }
        });
        box.setMaximumSize(box.getPreferredSize());   // measured with the prefix
        box.addActionListener(e -> {
            @SuppressWarnings("unchecked")
            T selected = (T) box.getSelectedItem();
            if (selected != null) {
                set(selected);
            }
        });
        views.add(() -> box.setSelectedItem(value));
        return box;
    }

    /** A menu with one radio item per value. */
    JMenu menu(String title, int mnemonic) {
        JMenu menu = new JMenu(title);
        menu.setMnemonic(mnemonic);
        ButtonGroup group = new ButtonGroup();
        List<JRadioButtonMenuItem> items = new ArrayList<>();
        for (T v : values) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(label.apply(v), v.equals(value));
            item.addActionListener(e -> set(v));
            group.add(item);
            menu.add(item);
            items.add(item);
        }
        views.add(() -> items.get(values.indexOf(value)).setSelected(true));
        return menu;
    }

    /** An action selecting the next ({@code step} = 1) or previous ({@code step} = −1) value, wrapping around. */
    Action cycle(String name, String tooltip, KeyStroke key, int step) {
        Action a = new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                int n = values.size();
                set(values.get(Math.floorMod(values.indexOf(value) + step, n)));
            }
        };
        a.putValue(Action.ACCELERATOR_KEY, key);
        a.putValue(Action.SHORT_DESCRIPTION, tooltip);
        return a;
    }
}
