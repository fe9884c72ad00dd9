package raylab.boundary;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;

import raylab.course.BoundaryHooks;

/**
 * The test JVM's hooks into the process boundary ({@link BoundaryHooks}, a service listed in
 * {@code META-INF/services/raylab.course.BoundaryHooks}): {@link Remote}'s student process and
 * {@link TrustedRender}.
 */
public final class TestJvmBoundary implements BoundaryHooks {
    @Override
    public void warmUp() {
        Remote.warmUp();
    }

    @Override
    public void switchTo(Path config) {
        Remote.switchTo(config);
    }

    @Override
    public void startTest(long limitNanos) {
        Remote.startTest(limitNanos);
    }

    @Override
    public long studentNanos() {
        return Remote.studentNanos();
    }

    @Override
    public long studentCpuNanos() {
        return Remote.studentCpuNanos();
    }

    @Override
    public void renderAll(List<String> scenes, long cpuBudgetNanos, PrintStream times) throws IOException {
        TrustedRender.renderAll(scenes, cpuBudgetNanos, times);
    }
}
