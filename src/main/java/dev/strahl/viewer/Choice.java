package dev.strahl.viewer;

import java.awt.Component;
import java.awt.event.ActionEvent;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Function;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.DefaultComboBoxModel;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JComboBox;
import javax.swing.JList;
import javax.swing.JMenu;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;

/**
 * One setting chosen from a short list (integrator, max depth, sampling, stop-at), shown both as
 * a toolbar combo box and as a menu of radio items, kept in step, with an action that cycles
 * through the values by keyboard. A value set from elsewhere (the command line, a scene file)
 * that is not in the list joins it where {@code order} puts it. Used on the event dispatch
 * thread only.
 */
final class Choice<T> {
    private final List<T> values;
    private final Comparator<? super T> order;
    private final Function<T, String> label;
    private final Consumer<T> onChange;
    private final List<Runnable> views = new ArrayList<>();
    private T value;
    /** The views are being brought in step with the value: their events are not the user's choices. */
    private boolean syncing;

    /**
     * @param values  the usual values, in the order shown
     * @param initial the value at first; joins the values if it is not one of them
     * @param order   where a value from elsewhere goes among the others; null if every value is in {@code values}
     */
    Choice(List<T> values, T initial, Comparator<? super T> order, Function<T, String> label, Consumer<T> onChange) {
        this.values = new ArrayList<>(values);
        this.order = order;
        this.label = label;
        this.onChange = onChange;
        include(initial);
        this.value = initial;
    }

    T value() {
        return value;
    }

    List<T> values() {
        return List.copyOf(values);
    }

    /**
     * Shows {@code v} as the current value without telling the listener: the setting was changed
     * elsewhere (another scene was opened with its own settings).
     */
    void show(T v) {
        if (v.equals(value)) {
            return;
        }
        include(v);
        value = v;
        sync();
    }

    private void include(T v) {
        if (values.contains(v)) {
            return;
        }
        if (order == null) {
            throw new IllegalArgumentException(v + " is not one of " + values);
        }
        values.add(v);
        values.sort(order);
    }

    private void sync() {
        syncing = true;
        try {
            views.forEach(Runnable::run);
        } finally {
            syncing = false;
        }
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
        sync();
        onChange.accept(v);
    }

    /** A combo box for the toolbar; {@code prefix} goes before each value ("depth ∞"). */
    JComboBox<T> comboBox(String prefix, String tooltip) {
        DefaultComboBoxModel<T> model = new DefaultComboBoxModel<>(new java.util.Vector<>(values));
        JComboBox<T> box = new JComboBox<>(model);
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
            if (selected != null && !syncing) {
                set(selected);
            }
        });
        views.add(() -> {
            if (model.getSize() != values.size()) {
                model.removeAllElements();
                model.addAll(values);
            }
            model.setSelectedItem(value);
        });
        return box;
    }

    /** A menu with one radio item per value. */
    JMenu menu(String title, int mnemonic) {
        JMenu menu = new JMenu(title);
        menu.setMnemonic(mnemonic);
        List<JRadioButtonMenuItem> items = new ArrayList<>();
        Runnable build = () -> {
            menu.removeAll();
            items.clear();
            ButtonGroup group = new ButtonGroup();
            for (T v : values) {
                JRadioButtonMenuItem item = new JRadioButtonMenuItem(label.apply(v), v.equals(value));
                item.addActionListener(e -> set(v));
                group.add(item);
                menu.add(item);
                items.add(item);
            }
        };
        build.run();
        views.add(() -> {
            if (items.size() != values.size()) {
                build.run();
            }
            items.get(values.indexOf(value)).setSelected(true);
        });
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
