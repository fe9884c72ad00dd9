package raylab.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/** Group: closest hit over its members, record contract, any-hit early exit, test counting. */
class GroupTest {
    static final Material M = new FlatColor(Color.WHITE, "white");

    /** A surface that counts how often it is asked, and hits (or not) at a fixed t. */
    static final class Probe extends Surface {
        final double hitT;
        int intersectCalls;
        int anyCalls;

        Probe(double hitT, String name) {
            super(M, name);
            this.hitT = hitT;
        }

        @Override
        public boolean intersect(IntersectionRecord rec, Ray ray) {
            intersectCalls++;
            if (Double.isNaN(hitT) || !ray.inRange(hitT) || hitT >= rec.t) {
                return false;
            }
            rec.set(hitT, ray.evaluate(hitT), new Vec3(0, 0, 1), this);
            return true;
        }

        @Override
        public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
            anyCalls++;
            return super.intersectsAny(ray, scratch);
        }

        @Override
        public BoundingBox boundingBox() {
            return new BoundingBox(Vec3.ZERO, Vec3.ZERO);
        }
    }

    private static List<Surface> spheresAlongZ() {
        List<Surface> list = new ArrayList<>();
        // Along the ray p = (0,0,10), d = (0,0,-2): sphere at z = c hit first at z = c + r,
        // t = (10 - c - r) / 2
        list.add(new Sphere(new Vec3(0, 0, 0), 1, M, "s0"));     // t = 4.5
        list.add(new Sphere(new Vec3(0, 0, 4), 0.5, M, "s4"));   // t = 2.75  (closest)
        list.add(new Sphere(new Vec3(0, 0, -6), 3, M, "s-6"));   // t = 6.5
        list.add(new Sphere(new Vec3(5, 0, 4), 0.5, M, "off"));  // missed
        list.add(new Box(new Vec3(-1, -1, 1), new Vec3(1, 1, 2), M, "box"));  // t = 4
        list.add(new Triangle(new Vec3(-1, -1, 3), new Vec3(1, -1, 3), new Vec3(0, 1, 3), M, "tri")); // t = 3.5
        return list;
    }

    @ParameterizedTest(name = "shuffle seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void closestHitWhateverTheOrder(long seed) {
        List<Surface> members = spheresAlongZ();
        Collections.shuffle(members, new Random(seed));
        Group g = new Group(members, "g");
        Ray ray = new Ray(new Vec3(0, 0, 10), new Vec3(0, 0, -2));
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(g.intersect(rec, ray), "seed " + seed + ": " + ray + " must hit " + members);
        assertEquals(2.75, rec.t, 1e-12, "seed " + seed + ": closest t along " + ray + " in " + members);
        assertEquals("s4", rec.surface.name(), "seed " + seed + ": closest surface in order " + members);
        assertEquals(new Vec3(0, 0, 4.5), rec.point, "hit point");
        assertEquals(6, rec.tests, "one test per member");
    }

    @Test
    void recordUntouchedWhenAllMiss() {
        Group g = new Group(spheresAlongZ(), "g");
        IntersectionRecord rec = new IntersectionRecord();
        Probe sentinel = new Probe(1, "sentinel");
        rec.set(100, new Vec3(7, 8, 9), new Vec3(0, 1, 0), sentinel);
        Ray miss = new Ray(new Vec3(0, 50, 10), new Vec3(0, 0, -1));
        assertFalse(g.intersect(rec, miss), "ray " + miss + " misses every member");
        assertEquals(100.0, rec.t, "t untouched");
        assertEquals(new Vec3(7, 8, 9), rec.point, "point untouched");
        assertEquals(new Vec3(0, 1, 0), rec.normal, "normal untouched");
        assertSame(sentinel, rec.surface, "surface untouched");
        assertSame(M, rec.material, "material untouched");
    }

    @Test
    void recordUntouchedWhenEveryHitIsFartherThanTheRecord() {
        Group g = new Group(spheresAlongZ(), "g");
        IntersectionRecord rec = new IntersectionRecord();
        Probe sentinel = new Probe(1, "sentinel");
        rec.set(2.5, new Vec3(0, 0, 5), new Vec3(0, 0, 1), sentinel);
        Ray ray = new Ray(new Vec3(0, 0, 10), new Vec3(0, 0, -2));
        assertFalse(g.intersect(rec, ray), "every hit is beyond record t = 2.5");
        assertEquals(2.5, rec.t, "t untouched");
        assertSame(sentinel, rec.surface, "surface untouched");
    }

    @Test
    void rangeOfTheRayIsRespected() {
        Group g = new Group(spheresAlongZ(), "g");
        IntersectionRecord rec = new IntersectionRecord();
        Ray segment = new Ray(new Vec3(0, 0, 10), new Vec3(0, 0, -2), 3.0, 4.2);
        assertTrue(g.intersect(rec, segment), "hits within [3, 4.2]: " + segment);
        assertEquals(3.25, rec.t, 1e-12, "sphere s4's far side at z = 3.5 (t = 3.25) is the first in range");
        assertEquals("s4", rec.surface.name(), "surface");
        rec.reset();
        Ray empty = new Ray(new Vec3(0, 0, 10), new Vec3(0, 0, -2), 10, 100);
        assertFalse(g.intersect(rec, empty), "nothing beyond t = 10 (the last exit is at t = 9.5): " + empty);
        assertFalse(rec.hasHit(), "no hit recorded");
    }

    @Test
    void intersectsAnyStopsAtTheFirstBlocker() {
        Probe miss = new Probe(Double.NaN, "miss");
        Probe blocker = new Probe(0.5, "blocker");
        Probe after1 = new Probe(0.2, "after1");
        Probe after2 = new Probe(0.7, "after2");
        Group g = new Group(List.of(miss, blocker, after1, after2), "g");
        IntersectionRecord scratch = new IntersectionRecord();
        Ray shadow = new Ray(Vec3.ZERO, new Vec3(1, 0, 0), 0, 1);
        assertTrue(g.intersectsAny(shadow, scratch), "the blocker at t = 0.5 is in [0, 1]");
        assertEquals(1, miss.anyCalls, "the first member is asked once");
        assertEquals(1, blocker.anyCalls, "the blocker is asked once");
        assertEquals(0, after1.intersectCalls + after1.anyCalls, "members after the blocker are not asked");
        assertEquals(0, after2.intersectCalls + after2.anyCalls, "members after the blocker are not asked");
        assertEquals(2, scratch.tests, "two members tested before stopping");
    }

    @Test
    void intersectsAnyFalseWhenAllBlockersAreOutOfRange() {
        Group g = new Group(List.of(new Probe(1.5, "far"), new Probe(-0.5, "behind")), "g");
        assertFalse(g.intersectsAny(new Ray(Vec3.ZERO, new Vec3(1, 0, 0), 0, 1), new IntersectionRecord()),
                "blockers at t = 1.5 and t = -0.5 are outside [0, 1]");
    }

    @Test
    void testsAreCountedAndAccumulate() {
        Group g = new Group(spheresAlongZ(), "g");
        IntersectionRecord rec = new IntersectionRecord();
        rec.tests = 10;
        g.intersect(rec, new Ray(new Vec3(0, 0, 10), new Vec3(0, 0, -1)));
        assertEquals(16, rec.tests, "10 before + 6 members");
        rec.reset();
        assertEquals(16, rec.tests, "reset keeps the test count");
        Group nested = new Group(List.of(g, new Sphere(new Vec3(0, 9, 0), 1, M, "x")), "nested");
        IntersectionRecord r2 = new IntersectionRecord();
        nested.intersect(r2, new Ray(new Vec3(0, 0, 10), new Vec3(0, 0, -1)));
        assertEquals(2 + 6, r2.tests, "nested group: 2 at the top, 6 inside");
    }

    @Test
    void boxCountAndConvexity() {
        Group g = new Group(spheresAlongZ(), "g");
        BoundingBox b = g.boundingBox();
        assertEquals(new Vec3(-3, -3, -9), b.min, "union of member boxes: min");
        assertEquals(new Vec3(5.5, 3, 4.5), b.max, "union of member boxes: max");
        assertEquals(6, g.primitiveCount(), "six primitives");
        assertFalse(g.isConvex(), "several members: not convex");
        assertTrue(new Group(List.of(new Sphere(Vec3.ZERO, 1, M, "s")), "one").isConvex(), "one sphere: convex");
        Group empty = new Group(List.of(), "empty");
        IntersectionRecord rec = new IntersectionRecord();
        assertFalse(empty.intersect(rec, new Ray(Vec3.ZERO, new Vec3(1, 0, 0))), "empty group never hits");
        assertNull(rec.surface, "no surface recorded");
        assertTrue(empty.boundingBox().isEmpty(), "empty group has an empty box");
        assertEquals(List.of("s0", "s4", "s-6", "off", "box", "tri"),
                g.members().stream().map(Surface::name).toList(), "members in order");
    }
}
