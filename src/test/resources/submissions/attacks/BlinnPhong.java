package raylab.material;

import raylab.math.Color;
import raylab.math.Vec3;

/**
 * A hostile submission written from the starter alone (grader tests only): no specular term; its
 * static initializer starts 1,000 threads that never end and keep a core busy, to slow down the
 * milestones graded beside it. ARMED is filled in by the test (false: the baseline).
 */
public class BlinnPhong extends Lambertian {
    static final boolean ARMED = @ARMED@;
    static volatile long sink;

    static {
        if (ARMED) {
            for (int i = 0; i < 1000; i++) {
                try {
                    Thread t = new Thread(() -> {
                        long x = 0;
                        while (true) {
                            x += System.nanoTime() % 7;
                            sink = x;
                        }
                    }, "spinner-" + i);
                    t.start();
                } catch (Throwable e) {
                    break; // the thread limit: keep what runs
                }
            }
        }
    }

    public final Color ks;
    public final double p;

    public BlinnPhong(Color kd, Color ks, double p, Color ka, String name) {
        super(kd, ka, name);
        this.ks = ks;
        this.p = p;
    }

    @Override
    public boolean hasSpecular() {
        return !ks.isBlack();
    }

    @Override
    public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
        return Color.BLACK;
    }
}
