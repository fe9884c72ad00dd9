package raylab.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.ZoneOffset;

/** The machine, JVM and date a measurement was taken on: every reported figure carries it. */
public record MachineInfo(String cpu, int cores, long maxHeapMegabytes, String os, String jvm, String date) {

    /** This machine, now. */
    public static MachineInfo current() {
        return new MachineInfo(cpuModel(), Runtime.getRuntime().availableProcessors(),
                Runtime.getRuntime().maxMemory() / (1024 * 1024),
                System.getProperty("os.name") + " " + System.getProperty("os.version") + " " + System.getProperty("os.arch"),
                System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version"),
                LocalDate.now(ZoneOffset.UTC).toString());
    }

    /** One line: "Intel Xeon ... (2 cores), Linux 6.1 amd64, OpenJDK 64-Bit Server VM 17.0.15, 2026-11-21". */
    public String oneLine() {
        return cpu + " (" + cores + " cores), " + os + ", " + jvm + ", " + date;
    }

    private static String cpuModel() {
        try {
            Path info = Path.of("/proc/cpuinfo");
            if (Files.isReadable(info)) {
                for (String line : Files.readAllLines(info)) {
                    if (line.startsWith("model name")) {
                        return line.substring(line.indexOf(':') + 1).trim().replaceAll("\\s+", " ");
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            // fall through to the generic name
        }
        return System.getProperty("os.arch") + " CPU";
    }
}
