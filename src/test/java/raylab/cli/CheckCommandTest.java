package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.PrintWriter;
import java.io.StringWriter;

import org.junit.jupiter.api.Test;

/** raylab check: bad input is one line with exit status 2. */
class CheckCommandTest {
    @Test
    void unknownMilestoneListsTheValidIds() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out), new PrintWriter(err), "check", "spheres");
        assertEquals(2, status, "exit status; stderr: " + err);
        assertEquals("raylab: unknown milestone 'spheres': valid ids are sphere, box, triangle, lambert, shadows,"
                + " phong", err.toString().strip());
    }
}
