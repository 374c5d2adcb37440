package minigolf.online.server;

import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;

/**
 * Runs one room's tasks one at a time, in order, on a shared pool: a room's state is touched by one
 * thread at a time without locks, and rooms run side by side. A task that throws is reported and the
 * room goes on (a bug in one message never stops a room).
 */
final class Actor implements Executor {
    private final Executor pool;
    private final Consumer<Throwable> onError;
    private final Queue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean scheduled = new AtomicBoolean();

    Actor(Executor pool, Consumer<Throwable> onError) {
        this.pool = pool;
        this.onError = onError;
    }

    @Override
    public void execute(Runnable task) {
        tasks.add(task);
        schedule();
    }

    private void schedule() {
        if (!tasks.isEmpty() && scheduled.compareAndSet(false, true)) pool.execute(this::drain);
    }

    private void drain() {
        try {
            for (int i = 0; i < 64; i++) { // then yield the thread to other rooms
                Runnable t = tasks.poll();
                if (t == null) break;
                try {
                    t.run();
                } catch (RuntimeException | StackOverflowError e) {
                    onError.accept(e);
                }
            }
        } finally {
            scheduled.set(false);
            schedule();
        }
    }
}
