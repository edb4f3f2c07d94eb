import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordedStackTrace;
import jdk.jfr.consumer.RecordingFile;

/**
 * The execution samples of a flight recording by the innermost strahl method (and line) they were
 * in, as shares of the samples whose stack passes through a method of FILTER (a class-name prefix,
 * e.g. dev.strahl.integrator for a render's work, dev.strahl.accel for the ray kernels).
 *
 *   java docs/bench/JfrTop.java RECORDING.jfr FILTER [TOP]
 */
public class JfrTop {
    public static void main(String[] args) throws Exception {
        String filter = args[1];
        int top = args.length > 2 ? Integer.parseInt(args[2]) : 25;
        Map<String, Integer> methods = new HashMap<>(), lines = new HashMap<>();
        int n = 0;
        try (RecordingFile f = new RecordingFile(Path.of(args[0]))) {
            while (f.hasMoreEvents()) {
                var e = f.readEvent();
                RecordedStackTrace st = e.getStackTrace();
                if (!e.getEventType().getName().equals("jdk.ExecutionSample") || st == null
                        || st.getFrames().stream().noneMatch(fr -> fr.getMethod().getType().getName().startsWith(filter))) {
                    continue;
                }
                n++;
                RecordedFrame own = st.getFrames().stream().filter(fr -> fr.getMethod().getType().getName().startsWith("dev.strahl")).findFirst().orElseThrow();
                String m = own.getMethod().getType().getName().replace("dev.strahl.", "") + "." + own.getMethod().getName();
                methods.merge(m, 1, Integer::sum);
                lines.merge(m + ":" + own.getLineNumber(), 1, Integer::sum);
            }
        }
        System.out.printf("%d samples through %s%n", n, filter);
        final int total = n;
        methods.entrySet().stream().sorted((a, b) -> b.getValue() - a.getValue()).limit(top)
                .forEach(x -> System.out.printf("%5.1f %%  %s%n", 100.0 * x.getValue() / total, x.getKey()));
        System.out.println("lines:");
        lines.entrySet().stream().sorted((a, b) -> b.getValue() - a.getValue()).limit(top)
                .forEach(x -> System.out.printf("%5.1f %%  %s%n", 100.0 * x.getValue() / total, x.getKey()));
    }
}
