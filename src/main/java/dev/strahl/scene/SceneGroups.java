package dev.strahl.scene;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.InstanceTransforms;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.joml.Matrix4d;

/**
 * The builder's groups and instances ({@link Scene.Builder#beginGroup}, {@link Scene.Builder#addInstance}):
 * each group's shapes collected into a geometry of its own, which the instances show moved by
 * their transforms. Groups do not nest, and an instance is placed in the scene itself, never in a
 * group. A group no instance shows is not built.
 */
final class SceneGroups {
    private final Map<String, GeometryBuilder> groups = new LinkedHashMap<>();
    private final List<String> instanceGroups = new ArrayList<>();
    private final List<Matrix4d> instanceMatrices = new ArrayList<>();
    private String open;

    /** Starts collecting group {@code name}; returns the builder its shapes go to. */
    GeometryBuilder begin(String name) {
        Objects.requireNonNull(name, "group name");
        if (open != null) {
            throw new IllegalStateException("group '" + open + "' is still open: groups do not nest (end it before starting '" + name + "')");
        }
        if (groups.containsKey(name)) {
            throw new IllegalArgumentException("group '" + name + "' is defined twice");
        }
        GeometryBuilder g = new GeometryBuilder();
        groups.put(name, g);
        open = name;
        return g;
    }

    void end() {
        if (open == null) {
            throw new IllegalStateException("no group is open");
        }
        open = null;
    }

    /** The open group's name, or null while shapes go into the scene itself. */
    String open() {
        return open;
    }

    void instance(String group, Transform transform) {
        Objects.requireNonNull(transform, "transform");
        if (open != null) {
            throw new IllegalStateException("an instance of '" + group + "' inside group '" + open + "': groups do not nest");
        }
        if (!groups.containsKey(group)) {
            throw new IllegalArgumentException("unknown group '" + group + "'" + (groups.isEmpty() ? " (no group is defined)" : " (defined: "
                    + String.join(", ", groups.keySet()) + ")"));
        }
        instanceGroups.add(group);
        instanceMatrices.add(transform.matrix());
    }

    /** The geometries of the groups that instances show, in the order of {@link #transforms()}' group numbers. */
    List<Geometry> geometries() {
        List<Geometry> out = new ArrayList<>();
        for (String name : usedGroups()) {
            out.add(groups.get(name).build());
        }
        return out;
    }

    /** Every instance's group (a number into {@link #geometries()}) and object-to-world matrix. */
    InstanceTransforms transforms() {
        List<String> used = usedGroups();
        int n = instanceGroups.size();
        int[] group = new int[n];
        double[] m = new double[12 * n];
        for (int i = 0; i < n; i++) {
            group[i] = used.indexOf(instanceGroups.get(i));
            Matrix4d t = instanceMatrices.get(i);
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 4; col++) {
                    m[12 * i + 4 * row + col] = t.get(col, row);
                }
            }
        }
        return new InstanceTransforms(group, m);
    }

    private List<String> usedGroups() {
        List<String> used = new ArrayList<>();
        for (String name : groups.keySet()) {
            if (instanceGroups.contains(name)) {
                used.add(name);
            }
        }
        return used;
    }
}
