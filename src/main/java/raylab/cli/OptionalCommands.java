package raylab.cli;

import picocli.CommandLine;

/**
 * Commands that exist only in the instructor's tree (the student release leaves their classes
 * out). They are looked up by name, so the command line works in both trees.
 */
final class OptionalCommands {
    static final String[] NAMES = {"raylab.course.release.ReleaseCommand", "raylab.course.release.AssignmentCommand", "raylab.grade.GradeCommand",
        "raylab.grade.ReferenceCommand", "raylab.grade.VariantCommand", "raylab.grade.BundleCommand",
        "raylab.grade.SelfCheckCommand",
        "raylab.grade.platform.GradeAllCommand", "raylab.study.StudyCommand"};

    private OptionalCommands() {
    }

    static void add(CommandLine cl, String className) {
        try {
            Object command = Class.forName(className).getDeclaredConstructor().newInstance();
            cl.addSubcommand(command);
        } catch (ReflectiveOperationException | LinkageError absent) {
            // Not in this tree (for example the student release): the command is simply missing.
        }
    }
}
