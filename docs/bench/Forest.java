import dev.strahl.bench.BenchMeshes;
import dev.strahl.scene.TriangleMesh;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Writes a forest for issue 31's memory figures: {@code tree.obj}, bench's generated displaced
 * sphere of 50 700 triangles (BenchMeshes.displacedSphere(65), the same bits on every machine),
 * and two scene files that place it N times on a grid, turned, scaled unequally and mirrored at
 * random (seed 31): {@code forest.json} with one group and N instances, {@code forest-flat.json}
 * with N copies of the mesh (each moved vertex by vertex, as strahl did before instancing).
 *
 *   java -cp target/strahl.jar docs/bench/Forest.java DIR [N]      (default N = 400)
 *   java -Xmx384m -jar target/strahl.jar render DIR/forest.json --width 320 --height 180 --spp 16 --stats DIR/forest-stats.json -o DIR/forest.png
 */
public class Forest {
    public static void main(String[] args) throws IOException {
        Path dir = Files.createDirectories(Path.of(args[0]));
        int n = args.length > 1 ? Integer.parseInt(args[1]) : 400;
        TriangleMesh tree = BenchMeshes.displacedSphere(65);
        try (PrintWriter out = new PrintWriter(Files.newBufferedWriter(dir.resolve("tree.obj")))) {
            float[] p = tree.positions();
            for (int i = 0; i < p.length; i += 3) {
                out.printf(Locale.ROOT, "v %s %s %s%n", p[i], p[i + 1], p[i + 2]);
            }
            int[] t = tree.indices();
            for (int i = 0; i < t.length; i += 3) {
                out.printf(Locale.ROOT, "f %d %d %d%n", t[i] + 1, t[i + 1] + 1, t[i + 2] + 1);
            }
        }
        int side = (int) Math.ceil(Math.sqrt(n));
        StringBuilder instances = new StringBuilder(), copies = new StringBuilder();
        SplittableRandom r = new SplittableRandom(31);
        for (int i = 0; i < n; i++) {
            double s = r.nextDouble(0.5, 1.0);
            String transform = String.format(Locale.ROOT,
                    "[{\"scale\": [%.4f, %.4f, %.4f]}, {\"rotate\": {\"axis\": [0, 1, 0], \"degrees\": %.2f}}, {\"translate\": [%.4f, %.4f, %.4f]}]",
                    (r.nextInt(4) == 0 ? -s : s), s * r.nextDouble(1.0, 2.2), s, r.nextDouble(360),
                    3.0 * (i % side - side / 2.0) + r.nextDouble(-0.8, 0.8), s, 3.0 * (i / side) + r.nextDouble(-0.8, 0.8));
            instances.append(String.format(",%n    {\"type\": \"instance\", \"group\": \"tree\", \"transform\": %s}", transform));
            copies.append(String.format(",%n    {\"type\": \"mesh\", \"file\": \"tree.obj\", \"material\": \"leaf\", \"transform\": %s}", transform));
        }
        double far = 3.0 * side;
        String head = String.format(Locale.ROOT, """
                {
                  "camera": {"lookFrom": [0, %.1f, %.1f], "lookAt": [0, 0, %.1f], "up": [0, 1, 0], "fov": 45},
                  "materials": {
                    "ground": {"type": "diffuse", "albedo": [0.35, 0.3, 0.25]},
                    "leaf": {"type": "diffuse", "albedo": [0.2, 0.45, 0.15]}
                  },
                  "lights": [{"type": "directional", "direction": [-0.4, -1, -0.6], "irradiance": [3, 2.8, 2.4]}],
                  "environment": [0.25, 0.3, 0.4],
                """, 0.35 * far, -0.25 * far, 0.45 * far);
        String ground = String.format(Locale.ROOT, "    {\"type\": \"triangles\", \"positions\": [%1$.1f, 0, -10, %2$.1f, 0, -10, %2$.1f, 0, %3$.1f, %1$.1f, 0, %3$.1f],"
                + " \"indices\": [0, 2, 1, 0, 3, 2], \"material\": \"ground\"}", -far, far, far + 10);
        Files.writeString(dir.resolve("forest.json"), head + "  \"groups\": {\"tree\": [{\"type\": \"mesh\", \"file\": \"tree.obj\", \"material\": \"leaf\"}]},\n"
                + "  \"shapes\": [\n" + ground + instances + "\n  ]\n}\n");
        Files.writeString(dir.resolve("forest-flat.json"), head + "  \"shapes\": [\n" + ground + copies + "\n  ]\n}\n");
        System.out.println(dir + ": tree.obj (" + tree.triangleCount() + " triangles), forest.json and forest-flat.json (" + n + " trees)");
    }
}
