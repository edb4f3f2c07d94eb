import dev.strahl.accel.Aggregate;
import dev.strahl.accel.Bvh;
import dev.strahl.accel.RayBatch;
import dev.strahl.accel.TraversalStack;
import dev.strahl.bench.BenchMeshes;
import dev.strahl.bench.BenchRays;
import dev.strahl.geometry.Geometry;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.mesh.MeshFiles;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Node visits and leaf block tests per ray of the eight-wide BVH on bench's ray sets (same seeds
 * and counts as {@code strahl bench}), counted by the scalar kernel, which visits what the SIMD
 * kernel visits; and the tree's memory. Deterministic: a change of the tree shows here where
 * timings on a shared machine cannot resolve it. A MESH named {@code generated} stands for bench's
 * three generated meshes (BenchMeshes.defaults(), the meshes {@code strahl bench} measures without
 * {@code --data}).
 *
 *   java -Dstrahl.countVisits=true -Dstrahl.simd=false -cp target/strahl.jar docs/bench/VisitCounts.java RAYS MESH [MESH ...]
 */
public class VisitCounts {
    public static void main(String[] args) throws Exception {
        int n = Integer.parseInt(args[0]);
        List<String> names = new ArrayList<>();
        List<Scene> scenes = new ArrayList<>();
        for (int m = 1; m < args.length; m++) {
            if (args[m].equals("generated")) {
                for (BenchMeshes.Generated generated : BenchMeshes.defaults()) {
                    names.add(generated.name());
                    scenes.add(Scene.builder().addMesh(generated.mesh().get(), MeshFiles.DEFAULT_MATERIAL).build());   // as bench builds it
                }
            } else {
                names.add(Path.of(args[m]).getFileName().toString());
                scenes.add(SceneLoader.load(Path.of(args[m])));
            }
        }
        for (int m = 0; m < scenes.size(); m++) {
            Scene scene = scenes.get(m);
            Aggregate bvh = World.of(scene).bvh();
            Geometry g = bvh.geometry();
            int side = (int) Math.max(1, Math.min(512, Math.sqrt(n / 4.0)));
            StringBuilder line = new StringBuilder(String.format("%-30s %9d triangles, %5.1f bytes/triangle (BVH %.1f, mesh %.1f)",
                    names.get(m), g.triangleCount(), (double) (bvh.byteSize() + g.byteSize()) / g.triangleCount(),
                    (double) bvh.byteSize() / g.triangleCount(), (double) g.byteSize() / g.triangleCount()));
            for (BenchRays.RaySet set : List.of(BenchRays.primary(scene.camera(), side, side, 4, 1), BenchRays.incoherent(g.bounds(), n, 2), BenchRays.shadow(g, n, 3))) {
                RayBatch batch = new RayBatch(set.count());
                double[] d = set.data();
                for (int i = 0, k = 0; i < set.count(); i++, k += 7) {
                    batch.set(i, d[k], d[k + 1], d[k + 2], d[k + 3], d[k + 4], d[k + 5], d[k + 6]);
                }
                TraversalStack stack = new TraversalStack();
                if (set.anyHit()) {
                    bvh.occluded(batch, 0, set.count(), stack);
                } else {
                    bvh.intersect(batch, 0, set.count(), stack, false);
                }
                line.append(String.format(";  %s: %.2f nodes, %.2f blocks a ray", set.name(), (double) stack.nodeVisits() / set.count(),
                        (double) stack.blockTests() / set.count()));
            }
            System.out.println(line);
        }
    }
}
