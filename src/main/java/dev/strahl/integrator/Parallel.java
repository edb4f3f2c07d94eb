package dev.strahl.integrator;

/**
 * Runs independent chunks of work on a render job's worker threads, for
 * {@link Integrator#prepareSample}. The integrator never creates threads: it cuts its work into a
 * fixed number of chunks (a number that does not depend on the thread count) and lets the job
 * run them, each chunk on some thread with that thread's {@link Integrator.Worker} as scratch.
 * A chunk's result must depend only on its index, never on the worker that ran it or the order.
 */
@FunctionalInterface
public interface Parallel {

    /**
     * Runs {@code task.run(i, worker)} for every i in [0, count), in any order and on any threads,
     * and returns when all have finished. If the render is cancelled meanwhile, chunks not yet
     * started may be skipped. An exception thrown by a chunk is rethrown here.
     */
    void forEach(int count, Task task);

    /** One chunk of work. */
    @FunctionalInterface
    interface Task {
        /** Does chunk {@code index}, using {@code worker} (made by the same integrator) as scratch. */
        void run(int index, Integrator.Worker worker);
    }

    /** Runs the chunks one after another on the calling thread with one worker: for tests and tools. */
    static Parallel sequential(Integrator.Worker worker) {
        return (count, task) -> {
            for (int i = 0; i < count; i++) {
                task.run(i, worker);
            }
        };
    }
}
