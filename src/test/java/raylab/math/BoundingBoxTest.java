package raylab.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import raylab.ray.Ray;

/** BoundingBox: union, centroid, area, longest axis, and the slab test. */
class BoundingBoxTest {
    private static final BoundingBox UNIT = new BoundingBox(new Vec3(0, 0, 0), new Vec3(1, 2, 3));

    @Test
    void emptyBoxIsTheIdentityOfUnion() {
        assertTrue(BoundingBox.EMPTY.isEmpty(), "EMPTY is empty");
        assertEquals(0.0, BoundingBox.EMPTY.halfArea(), "EMPTY has no area");
        BoundingBox u = BoundingBox.EMPTY.union(UNIT);
        assertEquals(UNIT.min, u.min, "EMPTY u B has B's min");
        assertEquals(UNIT.max, u.max, "EMPTY u B has B's max");
        BoundingBox p = BoundingBox.EMPTY.union(new Vec3(1, -2, 3));
        assertEquals(new Vec3(1, -2, 3), p.min, "EMPTY u point: min is the point");
        assertEquals(new Vec3(1, -2, 3), p.max, "EMPTY u point: max is the point");
        assertFalse(p.isEmpty(), "a point box is not empty");
        assertEquals(0.0, p.halfArea(), "a point has no area");
    }

    @Test
    void unionOfBoxesAndPoints() {
        BoundingBox other = new BoundingBox(new Vec3(-1, 1, 1), new Vec3(0.5, 5, 2));
        BoundingBox u = UNIT.union(other);
        assertEquals(new Vec3(-1, 0, 0), u.min, "union min");
        assertEquals(new Vec3(1, 5, 3), u.max, "union max");
        BoundingBox w = UNIT.union(new Vec3(4, -1, 1));
        assertEquals(new Vec3(0, -1, 0), w.min, "union with point: min");
        assertEquals(new Vec3(4, 2, 3), w.max, "union with point: max");
    }

    @Test
    void centroidExtentAreaAxis() {
        assertEquals(new Vec3(0.5, 1, 1.5), UNIT.centroid(), "centroid of [0,1]x[0,2]x[0,3]");
        assertEquals(new Vec3(1, 2, 3), UNIT.extent(), "extent");
        // half the surface area 2(1*2 + 2*3 + 3*1) = 22
        assertEquals(11.0, UNIT.halfArea(), "half area");
        assertEquals(2, UNIT.longestAxis(), "longest axis of extent (1,2,3)");
        assertEquals(0, new BoundingBox(Vec3.ZERO, new Vec3(5, 2, 3)).longestAxis(), "extent (5,2,3)");
        assertEquals(1, new BoundingBox(Vec3.ZERO, new Vec3(1, 7, 3)).longestAxis(), "extent (1,7,3)");
    }

    private static boolean hit(BoundingBox b, Ray r, double tMax) {
        return b.hit(r, 1 / r.d.x, 1 / r.d.y, 1 / r.d.z, tMax);
    }

    @Test
    void slabTest() {
        BoundingBox b = new BoundingBox(new Vec3(-1, -1, -1), new Vec3(1, 1, 1));
        Ray through = new Ray(new Vec3(-5, 0.2, 0.3), new Vec3(1, 0.01, 0));
        assertTrue(hit(b, through, Double.POSITIVE_INFINITY), "ray through the box: " + through);
        assertFalse(hit(b, through, 3.9), "segment ending before the box (entry at t=4): " + through);
        assertTrue(hit(b, through, 4.1), "segment ending inside the box: " + through);
        Ray miss = new Ray(new Vec3(-5, 2, 0), new Vec3(1, 0, 0));
        assertFalse(hit(b, miss, Double.POSITIVE_INFINITY), "ray above the box, parallel to x: " + miss);
        Ray behind = new Ray(new Vec3(5, 0, 0), new Vec3(1, 0, 0));
        assertFalse(hit(b, behind, Double.POSITIVE_INFINITY), "box behind the ray: " + behind);
        Ray inside = new Ray(new Vec3(0.5, 0.5, 0.5), new Vec3(-1, 2, -3));
        assertTrue(hit(b, inside, Double.POSITIVE_INFINITY), "ray starting inside: " + inside);
        Ray onFace = new Ray(new Vec3(-5, 1, 0), new Vec3(1, 0, 0));
        assertTrue(hit(b, onFace, Double.POSITIVE_INFINITY),
                "ray sliding along the face y = 1 (0 * inf in the slab test): " + onFace);
        Ray diagonal = new Ray(new Vec3(-3, -3, -3), new Vec3(1, 1, 1));
        assertTrue(hit(b, diagonal, Double.POSITIVE_INFINITY), "diagonal through corners: " + diagonal);
        Ray flatBox = new Ray(new Vec3(0.5, 0.5, 5), new Vec3(0, 0, -1));
        BoundingBox flat = new BoundingBox(new Vec3(0, 0, 0), new Vec3(1, 1, 0));
        assertTrue(hit(flat, flatBox, Double.POSITIVE_INFINITY), "ray across a flat box (a triangle's box)");
    }
}
