package raylab.architecture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import com.tngtech.archunit.core.domain.Dependency;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;

/**
 * The module lines (issue 38): every main class belongs to exactly one module, found by the source
 * root that holds its source file, and no class depends on a class of a module it may not use
 * ({@link Module#mayUse}). Read with ArchUnit from the compiled classes, so a fully qualified name
 * in code counts as much as an import; the failure names each offending dependency with its line.
 */
class ModuleLinesTest {
    private static final Path ROOT = Path.of("").toAbsolutePath();
    private static JavaClasses classes;
    private static final Map<String, Module> MODULE_OF = new java.util.HashMap<>();

    @BeforeAll
    static void importMainClasses() {
        classes = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPath(ROOT.resolve("target/classes"));
        for (JavaClass c : classes) {
            module(c).ifPresent(m -> MODULE_OF.put(c.getName(), m));
        }
    }

    /** The module of a class: where its source file is (a nested class: its outer class's file). */
    private static Optional<Module> module(JavaClass c) {
        Optional<String> file = c.getSource().flatMap(s -> s.getFileName()).map(Object::toString);
        String pkg = c.getPackageName().replace('.', '/');
        String name = file.orElse(c.getSimpleName() + ".java");
        if (!file.isPresent()) {
            JavaClass outer = c;
            while (outer.getEnclosingClass().isPresent()) {
                outer = outer.getEnclosingClass().get();
            }
            name = outer.getSimpleName() + ".java";
        }
        return Module.holding(ROOT, pkg + "/" + name);
    }

    @Test
    void everyMainClassBelongsToOneModule() {
        List<String> orphans = new ArrayList<>();
        Map<Module, Integer> counts = new EnumMap<>(Module.class);
        for (JavaClass c : classes) {
            Module m = MODULE_OF.get(c.getName());
            if (m == null) {
                orphans.add(c.getName() + " (source " + c.getSource().flatMap(s -> s.getFileName()).orElse("?") + ")");
            } else {
                counts.merge(m, 1, Integer::sum);
            }
        }
        assertEquals(List.of(), orphans, "main classes whose source file is in no module's source root");
        for (Module m : List.of(Module.LAB, Module.TOOLS, Module.GRADER, Module.AUTHORING)) {
            assertTrue(counts.getOrDefault(m, 0) > 5, "module " + m + " has classes: " + counts);
        }
    }

    @Test
    void noModuleUsesAModuleAboveIt() {
        TreeSet<String> violations = violations(classes, MODULE_OF);
        assertEquals("", String.join("\n", violations),
                "dependencies across the module lines in the wrong direction (docs/architecture.md): "
                        + violations.size());
    }

    /** A class that, were it in the lab, would use the tools: the check must find it. */
    static final class PlantedInTheLab {
        static String main() {
            return raylab.cli.Main.class.getName();
        }
    }

    @Test
    void theCheckFindsAPlantedUpwardDependency() {
        JavaClasses planted = new ClassFileImporter().importClasses(PlantedInTheLab.class, raylab.cli.Main.class);
        Map<String, Module> modules = Map.of(PlantedInTheLab.class.getName(), Module.LAB,
                raylab.cli.Main.class.getName(), Module.TOOLS);
        TreeSet<String> found = violations(planted, modules);
        assertEquals(1, found.size(), "one upward dependency: " + found);
        assertTrue(found.first().startsWith("LAB -> TOOLS: ") && found.first().contains("raylab.cli.Main")
                && found.first().contains("ModuleLinesTest.java:"), found.first());
        // The other way round is allowed: the tools may use the lab.
        assertEquals(Set.of(), violations(planted, Map.of(PlantedInTheLab.class.getName(), Module.TOOLS,
                raylab.cli.Main.class.getName(), Module.LAB)));
    }

    /** Each dependency of a class on a module its own may not use, described with its line. */
    private static TreeSet<String> violations(JavaClasses of, Map<String, Module> moduleOf) {
        TreeSet<String> out = new TreeSet<>();
        for (JavaClass c : of) {
            Module from = moduleOf.get(c.getName());
            if (from == null) {
                continue;
            }
            for (Dependency d : c.getDirectDependenciesFromSelf()) {
                Module to = moduleOf.get(d.getTargetClass().getBaseComponentType().getName());
                if (to != null && !from.mayUse().contains(to)) {
                    out.add(from + " -> " + to + ": " + d.getDescription());
                }
            }
        }
        return out;
    }

    @Test
    void theLabUsesNothingOfTheCourseButNotImplemented() {
        // The one class of raylab.course in the lab is the one the stubs throw.
        List<String> course = new ArrayList<>();
        for (JavaClass c : classes) {
            if (MODULE_OF.get(c.getName()) == Module.LAB && c.getPackageName().startsWith("raylab.course")) {
                course.add(c.getName());
            }
        }
        assertEquals(List.of("raylab.course.NotImplemented"), course);
    }
}
