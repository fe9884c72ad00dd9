package raylab.surface;

import raylab.course.NotImplemented;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * The triangle with vertices a, b, c. Its normal n = (b − a) × (c − a) / ‖(b − a) × (c − a)‖
 * points to the side from which a, b, c are seen counter-clockwise.
 */
public class Triangle extends Surface {
    public final Vec3 a;
    public final Vec3 b;
    public final Vec3 c;

    public Triangle(Vec3 a, Vec3 b, Vec3 c, Material material, String name) {
        super(material, name);
        this.a = a;
        this.b = b;
        this.c = c;
    }

    /**
     * Ray–triangle intersection (milestone {@code triangle}).
     *
     * <p>First the plane: with n = (b − a) × (c − a), the ray meets the plane (x − a)·n = 0 at
     * <pre>
     *   t = (a − p)·n / (d·n)          (no hit when d·n = 0: the ray is parallel to the plane)
     * </pre>
     * Then the point x = p + t·d is inside the triangle when it is on the inner side of all three
     * edges:
     * <pre>
     *   ((b − a) × (x − a))·n ≥ 0,   ((c − b) × (x − b))·n ≥ 0,   ((a − c) × (x − c))·n ≥ 0
     * </pre>
     * Record the hit if t is in range and closer than {@code outRecord.t}, with the unit normal
     * n / ‖n‖ (whichever side the ray comes from).
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        // BEGIN SOLUTION triangle
        // Watertight test (Woop, Benthin and Wald 2013; as in pbrt-v4's Triangle::Intersect).
        Vec3 n = b.minus(a).cross(c.minus(a));
        if (n.x == 0 && n.y == 0 && n.z == 0) {
            return false; // degenerate: zero area
        }
        // Ray space: translate p to the origin, rotate the axes so that d's largest component is
        // the third, shear so that d becomes (0, 0, 1). Every triangle sharing a vertex
        // transforms it with the same operations, so shared edges stay shared, bit for bit.
        int kz = largestAxis(ray.d);
        int kx = (kz + 1) % 3;
        int ky = (kx + 1) % 3;
        double sx = -ray.d.get(kx) / ray.d.get(kz);
        double sy = -ray.d.get(ky) / ray.d.get(kz);
        double sz = 1 / ray.d.get(kz);
        double[] aRay = toRaySpace(a, ray.p, kx, ky, kz, sx, sy, sz);
        double[] bRay = toRaySpace(b, ray.p, kx, ky, kz, sx, sy, sz);
        double[] cRay = toRaySpace(c, ray.p, kx, ky, kz, sx, sy, sz);
        // 2D edge functions at the origin (where the ray pierces the xy plane). Kahan's
        // difference of products with an FMA has a relative error below 2 ulps, so each sign is
        // exact and a shared edge gets opposite signs (or zero) in its two triangles.
        double e0 = differenceOfProducts(bRay[0], cRay[1], bRay[1], cRay[0]);
        double e1 = differenceOfProducts(cRay[0], aRay[1], cRay[1], aRay[0]);
        double e2 = differenceOfProducts(aRay[0], bRay[1], aRay[1], bRay[0]);
        // Inside (or on an edge) when no two edge functions have opposite signs.
        if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) {
            return false;
        }
        double det = e0 + e1 + e2;
        if (det == 0) {
            return false; // the ray lies in the triangle's plane
        }
        // Barycentric coordinates b0, b1, b2 (weights of a, b, c) and t, from the sheared z.
        double b0 = e0 / det;
        double b1 = e1 / det;
        double b2 = e2 / det;
        double t = b0 * aRay[2] + b1 * bRay[2] + b2 * cRay[2];
        if (inPlane(ray.p, n)) {
            // p lies in the triangle's plane (up to rounding), so the ray meets the plane at p:
            // a hit at t = 0 if p is in the triangle's box (docs/shading.md), else no hit.
            if (!inBox(ray.p)) {
                return false;
            }
            t = 0;
        }
        if (!ray.inRange(t) || t >= outRecord.t) {
            return false;
        }
        // The point from the barycentric coordinates lies closer to the triangle than p + t·d.
        Vec3 x = a.times(b0).plus(b.times(b1)).plus(c.times(b2));
        outRecord.set(t, x, n.normalize(), this);
        return true;
        // STUB
        // // TODO(triangle): hit the plane, then test the point against the three edges.
        // throw new NotImplemented("triangle", "Triangle.intersect");
        // END SOLUTION
    }

    // BEGIN SOLUTION triangle
    private static int largestAxis(Vec3 d) {
        double x = Math.abs(d.x);
        double y = Math.abs(d.y);
        double z = Math.abs(d.z);
        return x > y && x > z ? 0 : y > z ? 1 : 2;
    }

    /** Vertex v in ray space: v − p with axes permuted to (kx, ky, kz), then sheared. */
    private static double[] toRaySpace(Vec3 v, Vec3 p, int kx, int ky, int kz, double sx,
            double sy, double sz) {
        double x = v.get(kx) - p.get(kx);
        double y = v.get(ky) - p.get(ky);
        double z = v.get(kz) - p.get(kz);
        return new double[] {x + sx * z, y + sy * z, sz * z};
    }

    /**
     * Whether p lies in the triangle's plane up to the rounding of s = (a − p)·n, n = u × v with
     * u = b − a, v = c − a: |s| ≤ γ₈ Σᵢ |aᵢ − pᵢ| (|nᵢ| + Nᵢ), where Nᵢ sums the absolute values
     * of the two products in nᵢ (γₙ = nε/(1 − nε), ε = 2⁻⁵³; twice the rounding error of s).
     * Only for a plane that rounding leaves defined: Σ|nᵢ| &gt; γ₈ ΣNᵢ (not a sliver whose
     * computed normal is all rounding error).
     */
    private boolean inPlane(Vec3 p, Vec3 n) {
        Vec3 u = b.minus(a);
        Vec3 v = c.minus(a);
        Vec3 w = a.minus(p);
        double s = w.dot(n);
        double nx = Math.abs(u.y * v.z) + Math.abs(u.z * v.y);
        double ny = Math.abs(u.z * v.x) + Math.abs(u.x * v.z);
        double nz = Math.abs(u.x * v.y) + Math.abs(u.y * v.x);
        double bound = GAMMA8 * (Math.abs(w.x) * (Math.abs(n.x) + nx) + Math.abs(w.y) * (Math.abs(n.y) + ny)
                + Math.abs(w.z) * (Math.abs(n.z) + nz));
        double size = Math.abs(n.x) + Math.abs(n.y) + Math.abs(n.z);
        return Math.abs(s) <= bound && size > GAMMA8 * (nx + ny + nz);
    }

    /** Whether p lies in the triangle's bounding box (closed). */
    private boolean inBox(Vec3 p) {
        return p.x >= Math.min(Math.min(a.x, b.x), c.x) && p.x <= Math.max(Math.max(a.x, b.x), c.x)
                && p.y >= Math.min(Math.min(a.y, b.y), c.y) && p.y <= Math.max(Math.max(a.y, b.y), c.y)
                && p.z >= Math.min(Math.min(a.z, b.z), c.z) && p.z <= Math.max(Math.max(a.z, b.z), c.z);
    }

    private static final double GAMMA8 = 8 * 0x1p-53 / (1 - 8 * 0x1p-53);

    /** a·b − c·d accurate to 2 ulps (Kahan's algorithm): the FMA recovers c·d's rounding error. */
    private static double differenceOfProducts(double a, double b, double c, double d) {
        double cd = c * d;
        double error = Math.fma(-c, d, cd);
        return Math.fma(a, b, -cd) + error;
    }
    // END SOLUTION

    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(a.min(b).min(c), a.max(b).max(c));
    }
}
