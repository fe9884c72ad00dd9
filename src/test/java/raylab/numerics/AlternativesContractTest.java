package raylab.numerics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.Map;
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
import raylab.surface.Triangle;

/**
 * Every alternative method honours the Surface.intersect contract on ordinary rays: the same t
 * as the reference (within 10^-9 relative), nothing written when the hit is beyond tMax or not
 * closer than the record's t, or when the ray misses.
 */
@Tag("numerics")
class AlternativesContractTest {
    static final FlatColor M = new FlatColor(Color.WHITE, "m");

    static Map<String, Intersector> methods(SplittableRandom rnd, Vec3 c) {
        Sphere sphere = new Sphere(c, 1.5, M, "sphere");
        Box box = new Box(c.minus(new Vec3(1, 1.5, 0.5)), c.plus(new Vec3(1, 0.5, 1.5)), M, "box");
        Triangle tri = new Triangle(c.plus(Gen.unit(rnd).times(2)), c.plus(Gen.unit(rnd).times(2)),
                c.plus(Gen.unit(rnd).times(2)), M, "triangle");
        Map<String, Intersector> m = new LinkedHashMap<>();
        m.put("sphere reference", SphereMethods.reference(sphere));
        m.put("sphere textbook", SphereMethods.textbook(sphere));
        m.put("box reference", BoxMethods.reference(box));
        m.put("box naive slabs", BoxMethods.naiveSlabs(box));
        m.put("triangle reference", TriangleMethods.reference(tri));
        m.put("triangle lecture", TriangleMethods.lecture(tri));
        m.put("triangle Moller-Trumbore", TriangleMethods.mollerTrumbore(tri));
        return m;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void alternativesHonourTheContract(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int hits = 0;
        for (int i = 0; i < 300; i++) {
            Vec3 c = Gen.unit(rnd).times(3);
            Map<String, Intersector> m = methods(rnd, c);
            Vec3 p = Gen.unit(rnd).times(rnd.nextDouble(0, 10));
            Vec3 d = c.plus(Gen.unit(rnd).times(rnd.nextDouble(0, 2))).minus(p)
                    .times(Gen.logUniform(rnd, -2, 2));
            Ray ray = new Ray(p, d);
            Double referenceT = null;
            for (Map.Entry<String, Intersector> e : m.entrySet()) {
                String what = "seed " + seed + ": " + e.getKey() + " with " + ray;
                IntersectionRecord rec = new IntersectionRecord();
                boolean hit = e.getValue().intersect(rec, ray);
                if (e.getKey().endsWith("reference")) {
                    referenceT = hit ? rec.t : null;
                } else {
                    assertEquals(referenceT != null, hit, what + " disagrees with the reference");
                    if (hit) {
                        assertEquals(referenceT, rec.t, 1e-9 * referenceT, what);
                    }
                }
                if (!hit) {
                    assertFalse(rec.hasHit(), what + ": wrote a miss");
                    continue;
                }
                hits++;
                assertEquals(1.0, rec.normal.length(), 1e-12, what + ": normal not unit");
                IntersectionRecord closer = new IntersectionRecord();
                closer.t = rec.t;
                assertFalse(e.getValue().intersect(closer, ray), what + ": accepted t not closer");
                assertSame(null, closer.surface, what + ": record touched");
                IntersectionRecord r2 = new IntersectionRecord();
                Ray shorter = new Ray(p, d, 0, rec.t * 0.999);
                if (e.getValue().intersect(r2, shorter)) {
                    assertTrue(r2.t <= shorter.tMax, what + ": t beyond tMax");
                }
            }
        }
        assertTrue(hits > 600, "seed " + seed + ": too few hits " + hits);
    }
}
