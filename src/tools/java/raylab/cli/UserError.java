package raylab.cli;

/** A failure caused by what the user asked for: reported as one line with an exit status. */
public final class UserError extends RuntimeException {
    private static final long serialVersionUID = 1L;
    final int status;

    public UserError(String message, int status) {
        super(message);
        this.status = status;
    }

    /** A problem with the input (exit status 2). */
    public static UserError badInput(String message) {
        return new UserError(message, Main.BAD_INPUT);
    }
}
