package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import raylab.remote.StudentServer;

/**
 * Issue 35 item 6: the protocol has a channel of its own. A student process whose JVM logs every
 * garbage collection to its standard output ({@code -Xlog:gc*:stdout}, as the JVM writes its own
 * warnings at a thread or process limit) and whose code writes bytes shaped like a frame straight
 * to file descriptors 1 and 2 still answers every call, and what the code printed with
 * System.out still comes back as its output. (On standard output, the first such write broke the
 * protocol.) Every sandbox mode: {@code raylab.grade.ProtocolChannelGradeTest}.
 */
class ProtocolChannelTest {
    @Test
    void rawWritesAndJvmLogsNeverReachTheProtocol() {
        List<String> cmd = new ArrayList<>(StudentJvm.javaCommand(StudentProcessTest.classDirs(), 128,
                List.of("raylab.remote.Echo")));
        int jvm = StudentServer.CHANNEL_WRAPPER.size();
        assertEquals("java", java.nio.file.Path.of(cmd.get(jvm)).getFileName().toString(), "the JVM follows the wrapper: " + cmd);
        cmd.add(jvm + 1, "-Xlog:gc*:stdout");
        try (StudentProcess p = new StudentProcess(new StudentProcess.Config(cmd, null, StudentProcessTest.SERVED,
                20_000, 0))) {
            StringBuilder said = new StringBuilder();
            p.output(said::append);
            for (int i = 0; i < 20; i++) {
                assertEquals(8, p.call("raylab.remote.Echo", "raw", null, i), "call " + i);
            }
            assertEquals(1, p.starts(), "one student process for all the calls (none broke the protocol)");
            StringBuilder expected = new StringBuilder();
            for (int i = 0; i < 20; i++) {
                expected.append("said ").append(i).append('\n');
            }
            assertEquals(expected.toString(), said.toString(), "what System.out printed, and only that");
        }
    }
}
