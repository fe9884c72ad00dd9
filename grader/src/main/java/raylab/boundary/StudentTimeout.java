package raylab.boundary;

/** The student's code used more CPU time than allowed for one call; its process was stopped. */
public class StudentTimeout extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public StudentTimeout(String message) {
        super(message);
    }
}
