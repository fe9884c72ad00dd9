package raylab.numerics;

import java.util.SplittableRandom;

import raylab.math.Vec3;

/** Seeded generators shared by the numerics tests. */
final class Gen {
    static final double U = Math.ulp(1.0) / 2; // unit roundoff 2^-53

    private Gen() {
    }

    /** A uniformly distributed unit vector. */
    static Vec3 unit(SplittableRandom rnd) {
        while (true) {
            Vec3 v = new Vec3(rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1));
            double l = v.length();
            if (l > 0.1 && l <= 1) {
                return v.times(1 / l);
            }
        }
    }

    /** 10^(uniform in [lo, hi]). */
    static double logUniform(SplittableRandom rnd, double loExp, double hiExp) {
        return Math.pow(10, rnd.nextDouble(loExp, hiExp));
    }

    /** A random rotation, as the rows of a 3×3 matrix. */
    static Vec3[] rotation(SplittableRandom rnd) {
        Vec3 a = unit(rnd);
        Vec3 b = a.cross(unit(rnd)).normalize();
        Vec3 c = a.cross(b);
        return new Vec3[] {new Vec3(a.x, b.x, c.x), new Vec3(a.y, b.y, c.y), new Vec3(a.z, b.z, c.z)};
    }

    static Vec3 apply(Vec3[] rows, Vec3 v) {
        return new Vec3(rows[0].dot(v), rows[1].dot(v), rows[2].dot(v));
    }
}
