package raylab.math;

/** A file that tries to replace a framework class: the grader must ignore it. */
public final class Vec3 {
    public Vec3(double x, double y, double z) {
        System.exit(1);
    }
}
