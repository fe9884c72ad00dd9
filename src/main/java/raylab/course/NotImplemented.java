package raylab.course;

/**
 * Thrown by a student stub: names the milestone and the method still to write.
 *
 * <p>The renderer and the tests report it as one line, for example
 * {@code milestone 'sphere' is not implemented yet: write Sphere.intersect (assignments/01-sphere)}.
 */
public class NotImplemented extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String milestone;

    /** @param milestone the milestone id, as in its assignment.json; @param method what to write */
    public NotImplemented(String milestone, String method) {
        super("milestone '" + milestone + "' is not implemented yet: write " + method
                + " (see the handout in assignments/, then run ./raylab check " + milestone + ")");
        this.milestone = milestone;
    }

    /** The id of the milestone whose code is missing. */
    public String milestone() {
        return milestone;
    }
}
