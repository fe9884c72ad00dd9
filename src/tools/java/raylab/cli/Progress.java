package raylab.cli;

import java.io.Console;
import java.util.concurrent.atomic.AtomicInteger;

import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import raylab.scene.Scene;

/**
 * A progress bar on standard error for renders that take more than a second, shown only when
 * standard error is a terminal (never in logs, pipes or CI).
 */
final class Progress implements AutoCloseable {
    private static final long DELAY_MS = 1000;

    private final int tiles;
    private final AtomicInteger done = new AtomicInteger();
    private final Thread watcher;
    private volatile boolean finished;

    private Progress(int tiles, boolean show) {
        this.tiles = tiles;
        this.watcher = show ? new Thread(this::watch, "raylab-progress") : null;
        if (watcher != null) {
            watcher.setDaemon(true);
            watcher.start();
        }
    }

    static Progress start(Scene scene, int tile) {
        int tiles = ((scene.width + tile - 1) / tile) * ((scene.height + tile - 1) / tile);
        return new Progress(tiles, isTerminal());
    }

    void tileDone(int tile) {
        done.incrementAndGet();
    }

    private void watch() {
        try {
            Thread.sleep(DELAY_MS);
            if (finished) {
                return;
            }
            try (ProgressBar bar = new ProgressBarBuilder().setTaskName("render").setInitialMax(tiles)
                    .setUnit(" tiles", 1).setConsumer(new ConsoleProgressBarConsumer(System.err))
                    .setUpdateIntervalMillis(200).build()) {
                while (!finished) {
                    bar.stepTo(done.get());
                    Thread.sleep(100);
                }
                bar.stepTo(done.get());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        finished = true;
        if (watcher != null) {
            try {
                watcher.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Whether we talk to a terminal (Console.isTerminal on JDK 22+, console presence before). */
    static boolean isTerminal() {
        Console c = System.console();
        if (c == null || System.getenv("CI") != null) {
            return false;
        }
        try {
            return (Boolean) Console.class.getMethod("isTerminal").invoke(c);
        } catch (ReflectiveOperationException e) {
            return true;
        }
    }
}
