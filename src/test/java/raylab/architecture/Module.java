package raylab.architecture;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import raylab.course.SourceRoots;

/**
 * The project's modules (docs/architecture.md): each is a source root of the one Maven build, and
 * may use only the modules listed as below it. The lab is the ray tracer the starter holds as
 * source; the tools ship in the starter as a jar; the rest is the instructor's.
 */
enum Module {
    /** The ray tracer: math, ray, light, camera, material, shading, surface, scene, render, NotImplemented. */
    LAB(List.of(SourceRoots.LAB)),
    /** What students run but never read: cli, check, the test JVM, the student-side RPC server, inspect, bench. */
    TOOLS(List.of(SourceRoots.TOOLS)),
    /** The packed mesh engine, its generated traversals included. */
    MESH_ENGINE(List.of("src/mesh-engine/java", "target/generated-sources/mesh-engine")),
    /** The trusted side: grading, isolation, the client side of the boundary, reports, platforms. */
    GRADER(List.of("grader/src/main/java")),
    /** Release, study, the numerics oracle. */
    AUTHORING(List.of("src/authoring/java"));

    private final List<String> roots;

    Module(List<String> roots) {
        this.roots = roots;
    }

    List<String> roots() {
        return roots;
    }

    /** The modules this one may use (itself included). */
    Set<Module> mayUse() {
        return switch (this) {
            case LAB -> EnumSet.of(LAB);
            case TOOLS, MESH_ENGINE -> EnumSet.of(LAB, this);
            case GRADER -> EnumSet.of(LAB, TOOLS, GRADER);
            case AUTHORING -> EnumSet.of(LAB, TOOLS, MESH_ENGINE, GRADER, AUTHORING);
        };
    }

    /** Whether the starter has the module (as source or as the tools jar). */
    boolean ships() {
        return this == LAB || this == TOOLS;
    }

    /**
     * The module whose source roots hold {@code relativeSource} (a path below a root, such as
     * raylab/surface/Sphere.java), under the project folder {@code root}.
     */
    static Optional<Module> holding(Path root, String relativeSource) {
        for (Module m : values()) {
            for (String r : m.roots) {
                if (Files.isRegularFile(root.resolve(r).resolve(relativeSource))) {
                    return Optional.of(m);
                }
            }
        }
        return Optional.empty();
    }
}
