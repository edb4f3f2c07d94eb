package dev.strahl.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.RandomGenerator;

/**
 * A time-boxed fuzzing loop over a parser: inputs drawn from a jqwik {@link Arbitrary} (random
 * and mutated files) are written to a file and parsed on a worker thread. The parser may accept
 * an input or reject it with the project's own exception; anything else is a finding: another
 * exception or error (including {@link OutOfMemoryError}), or no answer within the per-input
 * timeout (a hang). Findings are shrunk (lines, then bytes, removed while the failure stays) and
 * saved under {@code target/fuzz-findings/NAME/} ({@link #output}), to be kept as regression cases.
 *
 * <p>A rejection must also read as the one line a user is shown: its message may not hold a control
 * character or a line break (a reader that quotes a hostile file's bytes as they are fails here) and
 * is at most {@value #MAX_MESSAGE} characters long.
 *
 * <p>The budget per parser is {@code -Dstrahl.fuzz.seconds} (default {@value #DEFAULT_SECONDS}; 0:
 * no limit) or {@code -Dstrahl.fuzz.inputs} inputs (default 0: no limit), whichever ends first; the
 * seed is {@code -Dstrahl.fuzz.seed} (default: a fixed one, so a run is repeatable), the time one
 * input may take {@code -Dstrahl.fuzz.timeout} seconds (default 5). The campaign of
 * docs/reliability/fuzz.sh runs a million inputs per parser this way.
 */
public final class Fuzzer {
    /** Ten parsers at 6.3 s: the minute and three seconds of {@code mvn verify} that nine took at 7 s. */
    public static final double DEFAULT_SECONDS = 6.3;
    /** The longest message a rejection may have (a path and a sentence, not a file's content). */
    public static final int MAX_MESSAGE = 1500;
    private static final Duration PER_INPUT = Duration.ofMillis((long) (1000 * Double.parseDouble(System.getProperty("strahl.fuzz.timeout", "5"))));
    private static final Duration SHRINK_BUDGET = Duration.ofSeconds(10);
    private static final int MAX_FINDINGS = 5;

    /** Parses one file; may throw the exception the parser is allowed to throw. */
    @FunctionalInterface
    public interface Target {
        void parse(Path file) throws Exception;
    }

    /** What an input that broke the parser did. */
    public record Finding(String what, byte[] input, Path saved) {}

    /** The figures of one run. */
    public record Report(String name, long inputs, long accepted, long rejected, double seconds, long seed, List<Finding> findings,
                         double slowestSeconds) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "fuzz %s: %d inputs in %.1f s (%.0f/s; %d accepted, %d rejected with the parser's error),"
                    + " seed %d, slowest input %.2f s, %d findings%s", name, inputs, seconds, inputs / seconds, accepted, rejected, seed,
                    slowestSeconds, findings.size(),
                    findings.isEmpty() ? "" : ": " + findings.stream().map(f -> f.what() + " -> " + f.saved()).toList());
        }
    }

    private final String name;
    private final Target target;
    private final Class<? extends Exception> allowed;
    private final Path file;
    private ExecutorService worker = newWorker();

    /**
     * @param name    parser name, for the report and the findings directory
     * @param target  the parser
     * @param allowed the one exception type it may throw (its parse error)
     * @param file    where each input is written before parsing (its name gives the extension)
     */
    public Fuzzer(String name, Target target, Class<? extends Exception> allowed, Path file) {
        this.name = name;
        this.target = target;
        this.allowed = allowed;
        this.file = file;
    }

    /** The time budget per parser; {@code Duration.ZERO} for none. */
    public static Duration budget() {
        return Duration.ofMillis((long) (1000 * Double.parseDouble(System.getProperty("strahl.fuzz.seconds", "" + DEFAULT_SECONDS))));
    }

    /** Where reports and findings go: {@code -Dstrahl.fuzz.out}, by default {@code target}. */
    public static Path output() {
        return Path.of(System.getProperty("strahl.fuzz.out", "target"));
    }

    /** The number of inputs per parser; 0 for no limit. */
    public static long inputs() {
        return Long.parseLong(System.getProperty("strahl.fuzz.inputs", "0"));
    }

    public static long seed() {
        return Long.parseLong(System.getProperty("strahl.fuzz.seed", "20260801"));
    }

    /** Runs inputs from {@code inputs} until the budget is spent or enough findings are made. */
    public Report run(Arbitrary<byte[]> inputs, Duration budget, long seed) throws IOException {
        return run(inputs, budget, 0, seed);
    }

    /**
     * Runs inputs until the time budget is spent ({@code Duration.ZERO}: never), {@code maxInputs}
     * have run (0: no limit) or enough findings are made; every 100 000 inputs it says how far it is.
     */
    public Report run(Arbitrary<byte[]> inputs, Duration budget, long maxInputs, long seed) throws IOException {
        RandomGenerator<byte[]> generator = inputs.generatorWithEmbeddedEdgeCases(1000);
        Random random = new Random(seed);
        long start = System.nanoTime();
        long deadline = budget.isZero() ? Long.MAX_VALUE : start + budget.toNanos();
        long count = 0;
        long accepted = 0;
        long rejected = 0;
        long slowest = 0;
        List<Finding> findings = new ArrayList<>();
        try {
            while (System.nanoTime() - deadline < 0 && (maxInputs == 0 || count < maxInputs) && findings.size() < MAX_FINDINGS) {
                byte[] input = generator.next(random).value();
                count++;
                long t0 = System.nanoTime();
                String failure = check(input);
                slowest = Math.max(slowest, System.nanoTime() - t0);
                if (count % 100_000 == 0) {
                    System.out.printf(Locale.ROOT, "fuzz %s: %d inputs, %.0f s, %d findings%n", name, count, (System.nanoTime() - start) * 1e-9,
                            findings.size());
                }
                if (failure == null) {
                    accepted++;
                } else if (failure.isEmpty()) {
                    rejected++;
                } else {
                    findings.add(save(shrink(input, failure), failure));
                }
            }
        } finally {
            worker.shutdownNow();
        }
        return new Report(name, count, accepted, rejected, (System.nanoTime() - start) * 1e-9, seed, findings, slowest * 1e-9);
    }

    /**
     * Parses one input: null if accepted, "" if rejected with the allowed exception, otherwise
     * what went wrong (the exception's class and message, or "hang").
     */
    public String check(byte[] input) throws IOException {
        Files.write(file, input);
        Future<?> f = worker.submit(() -> {
            target.parse(file);
            return null;
        });
        try {
            f.get(PER_INPUT.toMillis(), TimeUnit.MILLISECONDS);
            return null;
        } catch (TimeoutException e) {
            f.cancel(true);
            worker.shutdownNow();
            worker = newWorker();                  // the stuck thread is abandoned (a daemon)
            return "hang (no answer in " + PER_INPUT.toSeconds() + " s)";
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (allowed.isInstance(cause)) {
                return unprintable(cause.getMessage());
            }
            return cause.getClass().getName() + ": " + cause.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }

    /**
     * "" if {@code message} can be shown as the one line of an error, else why not (a finding): a
     * control character (a hostile file's bytes quoted as they are), a line or paragraph separator, or
     * more than {@value #MAX_MESSAGE} characters.
     */
    static String unprintable(String message) {
        if (message == null) {
            return "unprintable message: null";
        }
        if (message.length() > MAX_MESSAGE) {
            return "unprintable message: " + message.length() + " characters: " + message.substring(0, 200);
        }
        for (int i = 0; i < message.length(); i++) {
            char c = message.charAt(i);
            if (Character.isISOControl(c) || c == '\u2028' || c == '\u2029') {
                return String.format("unprintable message: character U+%04X at %d: %s", (int) c, i,
                        message.replaceAll("\\p{Cntrl}", "?"));
            }
        }
        return "";
    }

    /** Removes lines, then bytes, as long as the same kind of failure remains. */
    private byte[] shrink(byte[] input, String failure) throws IOException {
        String kind = failure.startsWith("hang") ? "hang" : failure.substring(0, Math.max(0, failure.indexOf(':')));
        long deadline = System.nanoTime() + SHRINK_BUDGET.toNanos();
        byte[] best = input;
        for (int chunk = Math.max(1, best.length / 2); chunk >= 1 && System.nanoTime() < deadline; chunk /= 2) {
            for (int at = 0; at + chunk <= best.length && System.nanoTime() < deadline; ) {
                byte[] candidate = new byte[best.length - chunk];
                System.arraycopy(best, 0, candidate, 0, at);
                System.arraycopy(best, at + chunk, candidate, at, best.length - at - chunk);
                String f = kind.equals("hang") ? null : check(candidate);
                if (f != null && !f.isEmpty() && f.startsWith(kind)) {
                    best = candidate;
                } else {
                    at += chunk;
                }
            }
        }
        return best;
    }

    private Finding save(byte[] input, String failure) throws IOException {
        Path dir = output().resolve("fuzz-findings").resolve(name);
        Files.createDirectories(dir);
        String fileName = file.getFileName().toString();
        String ext = fileName.substring(fileName.lastIndexOf('.'));
        String id;
        try {
            id = HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256").digest(input), 0, 8);
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
        Path saved = dir.resolve(id + ext);
        Files.write(saved, input);
        Files.writeString(dir.resolve(id + ".txt"), failure + "\n", StandardCharsets.UTF_8);
        return new Finding(failure, input, saved);
    }

    private static ExecutorService newWorker() {
        return Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fuzz-worker");
            t.setDaemon(true);
            return t;
        });
    }
}
