package dev.strahl.accel;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.InstanceTransforms;
import dev.strahl.geometry.Ray;
import java.util.List;

/**
 * A scene with instances: the scene's own primitives in a {@link Bvh} of their own (the base),
 * each group's primitives in one bottom-level {@link Bvh} built once however many instances show
 * it, and a top-level tree over the instances' world bounds ({@link InstanceTree}), visited nearest
 * child first. A ray meets
 * the base first, then the instances the top-level tree leads it to: each is entered with the ray
 * moved into its coordinates ({@link InstanceTransforms#rayToObject}, into the stack's scratch
 * ray, so nothing is allocated per ray) and traced by the group's tree with its kernels, the SIMD
 * one or its scalar twin, with the same bits either way. A hit in an instance names the group's
 * primitive and the instance ({@link Hit#instance}); its distance is along the world ray.
 */
public final class TwoLevelBvh implements Aggregate {
    private final Aggregate base;
    private final Aggregate[] groups;
    private final InstanceTransforms instances;
    private final InstanceTree tree;
    private final boolean everyInstance;

    private TwoLevelBvh(Aggregate base, Aggregate[] groups, InstanceTransforms instances, InstanceTree tree, boolean everyInstance) {
        this.base = base;
        this.groups = groups;
        this.instances = instances;
        this.tree = tree;
        this.everyInstance = everyInstance;
    }

    /**
     * Builds the base's tree, each group's tree once, and the tree over the instances. The
     * geometries of the result ({@link #geometry()}, {@link #groupGeometry}) are in leaf order.
     */
    public static TwoLevelBvh build(Geometry base, List<Geometry> groups, InstanceTransforms instances) {
        Aggregate[] trees = new Aggregate[groups.size()];
        Aabb[] boxes = new Aabb[groups.size()];
        for (int g = 0; g < trees.length; g++) {
            trees[g] = Bvh.build(groups.get(g));
            boxes[g] = groups.get(g).bounds();
        }
        for (int i = 0; i < instances.count(); i++) {
            if (instances.group(i) < 0 || instances.group(i) >= trees.length) {
                throw new IllegalArgumentException("instance " + i + " shows group " + instances.group(i) + " of " + trees.length);
            }
        }
        return new TwoLevelBvh(Bvh.build(base), trees, instances, InstanceTree.build(instances, boxes), false);
    }

    /** The same structure traversed by the SIMD kernel or by the scalar one (see {@link Bvh#withSimd}). */
    public TwoLevelBvh withSimd(boolean on) {
        Aggregate[] g = new Aggregate[groups.length];
        for (int i = 0; i < g.length; i++) {
            g[i] = ((Bvh) groups[i]).withSimd(on);
        }
        return new TwoLevelBvh(((Bvh) base).withSimd(on), g, instances, tree, everyInstance);
    }

    /** Every primitive of the base and of each group tested, and every instance entered, without a tree. */
    @Override
    public Aggregate bruteForce() {
        Aggregate[] g = new Aggregate[groups.length];
        for (int i = 0; i < g.length; i++) {
            g[i] = groups[i].bruteForce();
        }
        return new TwoLevelBvh(base.bruteForce(), g, instances, tree, true);
    }

    @Override
    public Geometry geometry() {
        return base.geometry();
    }

    /** Group g's primitives, in the order its hits' primitive ids refer to. */
    public Geometry groupGeometry(int g) {
        return groups[g].geometry();
    }

    public int groupCount() {
        return groups.length;
    }

    public InstanceTransforms instances() {
        return instances;
    }

    @Override
    public boolean intersect(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        boolean found = base.intersect(ray, hit, stack, cullBackFaces);
        if (found) {
            hit.instance = -1;
        }
        if (everyInstance) {
            for (int i = 0; i < instances.count(); i++) {
                found |= enter(i, ray, hit, stack, cullBackFaces);
            }
            return found;
        }
        if (tree.isEmpty() || !tree.prepare(ray, stack)) {
            return found;
        }
        // Nearest child first; a node popped beyond the closest hit so far is dropped.
        final int[] nodes = stack.topNodes;
        final double[] entries = stack.topEntries;
        int sp = 0, node = 0;
        while (true) {
            if (tree.isLeaf(node)) {
                for (int k = tree.first(node), end = k + tree.count(node); k < end; k++) {
                    found |= enter(tree.instance(k), ray, hit, stack, cullBackFaces);
                }
            } else {
                int l = tree.left(node), r = tree.right(node);
                double tl = tree.entry(l, stack, ray.tMax), tr = tree.entry(r, stack, ray.tMax);
                if (tl <= tr) {
                    if (tr != InstanceTree.MISS) {
                        nodes[sp] = r;
                        entries[sp++] = tr;
                    }
                    if (tl != InstanceTree.MISS) {
                        node = l;
                        continue;
                    }
                } else {
                    if (tl != InstanceTree.MISS) {
                        nodes[sp] = l;
                        entries[sp++] = tl;
                    }
                    node = r;
                    continue;
                }
            }
            do {
                if (sp == 0) {
                    return found;
                }
                node = nodes[--sp];
            } while (entries[sp] > ray.tMax);
        }
    }

    /** Instance i's closest hit, if closer than ray.tMax: recorded in {@code hit}, ray.tMax shortened. */
    private boolean enter(int i, Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        Ray local = stack.instanceRay;
        Hit h = stack.instanceHit;
        double scale = instances.rayToObject(i, ray, local);
        h.reset();
        if (!groups[instances.group(i)].intersect(local, h, stack, cullBackFaces)) {
            return false;
        }
        double t = h.t / scale;
        if (!(t < ray.tMax)) {
            return false;
        }
        ray.tMax = t;
        hit.t = t;
        hit.prim = h.prim;
        hit.b1 = h.b1;
        hit.b2 = h.b2;
        hit.instance = i;
        return true;
    }

    @Override
    public boolean occluded(Ray ray, TraversalStack stack) {
        if (base.occluded(ray, stack)) {
            return true;
        }
        if (everyInstance) {
            for (int i = 0; i < instances.count(); i++) {
                if (blocks(i, ray, stack)) {
                    return true;
                }
            }
            return false;
        }
        if (tree.isEmpty() || !tree.prepare(ray, stack)) {
            return false;
        }
        final int[] nodes = stack.topNodes;
        int sp = 0, node = 0;
        while (true) {
            if (tree.isLeaf(node)) {
                for (int k = tree.first(node), end = k + tree.count(node); k < end; k++) {
                    if (blocks(tree.instance(k), ray, stack)) {
                        return true;
                    }
                }
            } else {
                int l = tree.left(node), r = tree.right(node);
                if (tree.entry(r, stack, ray.tMax) != InstanceTree.MISS) {
                    nodes[sp++] = r;
                }
                if (tree.entry(l, stack, ray.tMax) != InstanceTree.MISS) {
                    nodes[sp++] = l;
                }
            }
            if (sp == 0) {
                return false;
            }
            node = nodes[--sp];
        }
    }

    private boolean blocks(int i, Ray ray, TraversalStack stack) {
        Ray local = stack.instanceRay;
        instances.rayToObject(i, ray, local);
        return groups[instances.group(i)].occluded(local, stack);
    }

    /** The base's, every group's (once) and the top-level tree's bytes, with the instances' matrices. */
    @Override
    public long byteSize() {
        long bytes = base.byteSize() + tree.byteSize() + instances.byteSize();
        for (Aggregate g : groups) {
            bytes += g.byteSize();
        }
        return bytes;
    }

    @Override
    public String kernel() {
        return "two-level (" + instances.count() + " instances of " + groups.length + " groups), " + base.kernel();
    }
}
