package raylab.surface;

class SphereTest {
    // a student's "test" that would pass everything: ignored by the grader
}
