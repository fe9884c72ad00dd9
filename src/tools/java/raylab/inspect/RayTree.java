package raylab.inspect;

import java.util.ArrayList;
import java.util.List;

import raylab.math.Color;
import raylab.math.Vec3;

/**
 * The ray tree of one pixel, as far as a comparison with the reference needs it: the eye ray's
 * closest hit (surface, t, point x, normal n), and for each light its shadow ray and terms:
 * <pre>
 *   L = ka·Ia + Σ_i [ kd·I_i·max(0, n·l_i) + ks·I_i·max(0, n·h_i)^p ]
 * </pre>
 * One ray through the pixel centre. A value the code never produced is null (the ambient term
 * of a shade() that leaves it out, the diffuse term of a light found blocked).
 */
public final class RayTree {
    /** What became of a light at the shaded point. */
    public enum State {
        /** shade() never asked for the direction to this light. */
        NOT_LOOKED,
        /** Behind the surface (n·l ≤ 0): no shadow ray, no terms. */
        BEHIND,
        /** In front; the render plan traces no shadow ray toward it (nothing can block it). */
        NO_SHADOW_RAY,
        /** In front; the shadow ray reaches the light. */
        CLEAR,
        /** In front; the shadow ray is blocked. */
        BLOCKED
    }

    /** One light's part of the tree. */
    public static final class Light {
        public final String name;
        public State state = State.NOT_LOOKED;
        /** The blocker's name and its t on the shadow ray (t = 1 is the light), when BLOCKED. */
        public String blocker;
        public double blockerT = Double.NaN;
        /** kd·I·max(0, n·l), or null when shade() did not ask for it. */
        public Color diffuse;
        /** ks·I·max(0, n·h)^p, or null when not asked for (or the plan needs none). */
        public Color specular;

        public Light(String name) {
            this.name = name;
        }
    }

    public final int x;
    public final int y;
    /** The eye ray r(t) = p + t·d (the camera's, the same for the student and the reference). */
    public final Vec3 eyeP;
    public final Vec3 eyeD;
    /** The closest surface's name, or null when the eye ray hits nothing. */
    public String surface;
    /** Its kind (Sphere, Box, Triangle, Mesh, ...), for naming the method that computed the hit. */
    public String kind;
    public double t = Double.NaN;
    public Vec3 point;
    /** The normal intersect() recorded (outward for a correct intersect). */
    public Vec3 normal;
    /** Whether the material is shaded by the lights (false: a flat colour). */
    public boolean lit;
    /** ka·Ia as shade() added it (summed if added more than once), or null when never added. */
    public Color ambient;
    /** How many times shade() added the ambient term. */
    public int ambientAdded;
    public final List<Light> lights = new ArrayList<>();
    /** The pixel's colour L (linear). */
    public Color colour;

    public RayTree(int x, int y, Vec3 eyeP, Vec3 eyeD) {
        this.x = x;
        this.y = y;
        this.eyeP = eyeP;
        this.eyeD = eyeD;
    }

    /** The light of this name (created, in order, when first seen). */
    public Light light(String name) {
        for (Light l : lights) {
            if (l.name.equals(name)) {
                return l;
            }
        }
        Light l = new Light(name);
        lights.add(l);
        return l;
    }

    public boolean hit() {
        return surface != null;
    }
}
