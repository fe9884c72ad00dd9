package raylab.cli;

/**
 * A command that a build adds to {@code raylab}'s own (the instructor's: release, grade, bundle,
 * study, ...). A service: each such picocli command class implements this interface and is listed
 * in {@code META-INF/services/raylab.cli.OptionalCommand} of its build, in the order
 * {@code --help} lists them. The student starter has no such classes and its release lists none,
 * so its command line simply lacks them.
 */
public interface OptionalCommand {
}
