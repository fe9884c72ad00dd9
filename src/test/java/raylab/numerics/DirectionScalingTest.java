package raylab.numerics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Box;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * The same ray with its direction scaled by 10^-8 .. 10^8 (powers of ten, so the scaled
 * direction is rounded) must give the same hit point, within 8 ulps of the largest coordinate
 * of p and of the point (the size of the numbers the point is computed from).
 */
@Tag("numerics")
class DirectionScalingTest {
    static final FlatColor M = new FlatColor(Color.WHITE, "m");

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void scalingTheDirectionKeepsTheHitPoint(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        double[] worst = new double[3];
        int checked = 0;
        for (int i = 0; i < 600; i++) {
            double scale = Gen.logUniform(rnd, -3, 3);
            Vec3 center = Gen.unit(rnd).times(scale * Gen.logUniform(rnd, 0, 3));
            Surface s;
            switch (i % 3) {
                case 0 -> s = new Sphere(center, scale, M, "sphere");
                case 1 -> s = new Box(center.minus(new Vec3(scale, scale, scale)),
                        center.plus(new Vec3(scale, 2 * scale, 0.5 * scale)), M, "box");
                default -> s = new Triangle(center.plus(Gen.unit(rnd).times(scale)),
                        center.plus(Gen.unit(rnd).times(scale)),
                        center.plus(Gen.unit(rnd).times(scale)), M, "triangle");
            }
            Vec3 p = center.plus(Gen.unit(rnd).times(5 * scale));
            Vec3 d0 = center.plus(Gen.unit(rnd).times(0.3 * scale)).minus(p);
            IntersectionRecord first = new IntersectionRecord();
            if (!s.intersect(first, new Ray(p, d0))) {
                continue;
            }
            checked++;
            for (int k = -8; k <= 8; k++) {
                double factor = Math.pow(10, k);
                Vec3 d = d0.times(factor);
                Ray ray = new Ray(p, d);
                IntersectionRecord rec = new IntersectionRecord();
                String what = "seed " + seed + ": " + ray + " (direction times 1e" + k + ") vs " + s;
                assertTrue(s.intersect(rec, ray), what + ": misses, unscaled hit " + first);
                double size = Math.max(p.maxAbs(), first.point.maxAbs());
                double ulps = rec.point.minus(first.point).maxAbs() / Math.ulp(size);
                worst[i % 3] = Math.max(worst[i % 3], ulps);
                assertTrue(ulps <= 8, what + ": point " + rec.point + " differs from " + first.point
                        + " by " + ulps + " ulps");
                assertEquals(first.normal.x, rec.normal.x, 1e-12, what);
            }
        }
        System.out.printf("direction scaling seed %d: %d rays x 17 scales, worst point difference"
                + " sphere %.1f, box %.1f, triangle %.1f ulps%n", seed, checked, worst[0], worst[1],
                worst[2]);
        assertTrue(checked > 300, "seed " + seed + ": too few hits " + checked);
    }
}
