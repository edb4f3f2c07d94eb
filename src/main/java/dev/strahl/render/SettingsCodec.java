package dev.strahl.render;

import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.time.Duration;
import java.util.Collections;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * The one description of a render's settings by name, read off the records of {@link RenderSettings}
 * rather than listed by hand: a setting is named by its record component, the four parts being
 * transparent ({@code width}, {@code seed}, {@code maxDepth}, {@code threads}), a value record inside
 * a part by a prefix ({@code photons.photonsPerIteration}). The checkpoint's fingerprint, the
 * settings a cluster coordinator sends its members and {@code render --stats} are all written from
 * {@link #entries}, so a setting added to a part travels everywhere by itself; {@link #settings}
 * rebuilds the records from the text form ({@link #text}), by the same walk.
 */
final class SettingsCodec {
    private SettingsCodec() {}

    /** Every setting with its value (Integer, Long, Double, Boolean, an enum, Duration, Set of Aov), in declaration order. */
    static Map<String, Object> entries(RenderSettings settings) {
        Map<String, Object> out = new LinkedHashMap<>();
        for (RecordComponent part : RenderSettings.class.getRecordComponents()) {
            collect(out, "", (Record) read(part, settings));
        }
        return Collections.unmodifiableMap(out);
    }

    private static void collect(Map<String, Object> out, String prefix, Record record) {
        for (RecordComponent c : record.getClass().getRecordComponents()) {
            Object value = read(c, record);
            if (value instanceof Record nested) {
                collect(out, prefix + c.getName() + ".", nested);
            } else {
                out.put(prefix + c.getName(), value);
            }
        }
    }

    private static Object read(RecordComponent c, Record record) {
        try {
            return c.getAccessor().invoke(record);
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot read setting " + c.getName(), e);
        }
    }

    /** The value as {@link #settings} reads it back: sets of feature buffers as their names joined by ','. */
    static String format(Object value) {
        if (value instanceof Set<?> set) {
            return set.stream().map(v -> ((Enum<?>) v).name()).collect(Collectors.joining(","));
        }
        return String.valueOf(value);
    }

    /** "name=value;name=value": what {@link #parse} reads. */
    static String text(Map<String, ?> entries) {
        return entries.entrySet().stream().map(e -> e.getKey() + "=" + format(e.getValue())).collect(Collectors.joining(";"));
    }

    /** The name=value pairs of a text, in order; parts without '=' are skipped. */
    static Map<String, String> parse(String text) {
        Map<String, String> m = new LinkedHashMap<>();
        for (String part : text.split(";")) {
            int eq = part.indexOf('=');
            if (eq > 0) {
                m.put(part.substring(0, eq), part.substring(eq + 1));
            }
        }
        return m;
    }

    /**
     * The settings of a text made from {@link #entries}: every setting must be named, and no other.
     *
     * @throws IllegalArgumentException naming a setting that is missing, unknown or of a bad value
     */
    static RenderSettings settings(Map<String, String> values) {
        Map<String, String> left = new LinkedHashMap<>(values);
        Object[] parts = new Object[RenderSettings.class.getRecordComponents().length];
        int i = 0;
        for (RecordComponent part : RenderSettings.class.getRecordComponents()) {
            parts[i++] = build(part.getType(), "", left);
        }
        if (!left.isEmpty()) {
            throw new IllegalArgumentException("unknown setting '" + left.keySet().iterator().next() + "'");
        }
        return (RenderSettings) construct(RenderSettings.class, parts);
    }

    private static Object build(Class<?> type, String prefix, Map<String, String> left) {
        RecordComponent[] components = type.getRecordComponents();
        Object[] args = new Object[components.length];
        for (int i = 0; i < components.length; i++) {
            RecordComponent c = components[i];
            String name = prefix + c.getName();
            if (c.getType().isRecord()) {
                args[i] = build(c.getType(), name + ".", left);
                continue;
            }
            String text = left.remove(name);
            if (text == null) {
                throw new IllegalArgumentException("setting '" + name + "' missing");
            }
            try {
                args[i] = value(c, text);
            } catch (RuntimeException e) {
                throw new IllegalArgumentException("setting '" + name + "': bad value '" + text + "'", e);
            }
        }
        return construct(type, args);
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private static Object value(RecordComponent c, String text) {
        Class<?> t = c.getType();
        if (t == int.class) {
            return Integer.parseInt(text);
        } else if (t == long.class) {
            return Long.parseLong(text);
        } else if (t == double.class) {
            return Double.parseDouble(text);
        } else if (t == boolean.class) {
            if (!text.equals("true") && !text.equals("false")) {
                throw new IllegalArgumentException(text);
            }
            return Boolean.parseBoolean(text);
        } else if (t.isEnum()) {
            return Enum.valueOf((Class<Enum>) t, text);
        } else if (t == Duration.class) {
            return Duration.parse(text);
        } else if (t == Set.class && c.getGenericType() instanceof ParameterizedType p && p.getActualTypeArguments()[0] == Aov.class) {
            Set<Aov> set = EnumSet.noneOf(Aov.class);
            for (String name : text.split(",")) {
                if (!name.isEmpty()) {
                    set.add(Aov.valueOf(name));
                }
            }
            return set;
        }
        throw new IllegalStateException("no text form for a setting of type " + c.getGenericType());
    }

    private static Object construct(Class<?> type, Object[] args) {
        Class<?>[] types = new Class<?>[args.length];
        RecordComponent[] components = type.getRecordComponents();
        for (int i = 0; i < types.length; i++) {
            types[i] = components[i].getType();
        }
        try {
            return type.getDeclaredConstructor(types).newInstance(args);
        } catch (java.lang.reflect.InvocationTargetException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;                              // the record's own check: its message names the setting
            }
            throw new IllegalStateException(e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot make " + type.getSimpleName(), e);
        }
    }
}
