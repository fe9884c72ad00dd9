package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.util.Set;

import org.junit.jupiter.api.Test;

/** The text constants of a class file, as a submission could copy them out of a hidden test. */
class ClassStringsTest {
    /** Long and double constants take two constant-pool entries each: read past them. */
    static final long BIG = 1L << 40;
    static final double HUGE = 1e300;
    static final String MESSAGE = "a message only this class holds, 42";

    @Test
    void readsTheStringConstantsAndNamesOfAClassFile() throws IOException {
        byte[] bytes;
        try (InputStream in = ClassStringsTest.class.getResourceAsStream("ClassStringsTest.class")) {
            bytes = in.readAllBytes();
        }
        Set<String> s = ClassStrings.of(bytes);
        assertTrue(s.contains(MESSAGE), s.toString());
        assertTrue(s.contains("raylab/grade/ClassStringsTest"), s.toString());
        assertTrue(s.contains("readsTheStringConstantsAndNamesOfAClassFile"), s.toString());
        assertTrue(ClassStrings.of(new byte[] {1, 2, 3}).isEmpty());
        assertTrue(ClassStrings.of(java.util.Arrays.copyOf(bytes, 40)).size() < s.size(), "a truncated file: what was read");
        assertTrue(s.contains("BIG") && s.contains("HUGE"), s.toString());
    }
}
