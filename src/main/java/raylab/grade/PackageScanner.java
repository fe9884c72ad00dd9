package raylab.grade;

/** The package a Java source declares: {@link raylab.course.PackageScanner}'s logic, under the grader's name. */
final class PackageScanner {
    private PackageScanner() {
    }

    static String packageOf(String source) {
        return raylab.course.PackageScanner.packageOf(source);
    }

    static String unescape(String s) {
        return raylab.course.PackageScanner.unescape(s);
    }
}
