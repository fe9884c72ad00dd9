package raylab.grade;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * The text constants of a class file (its constant pool's UTF-8 entries), read without loading
 * the class: what a submission could copy out of a hidden test's class file.
 */
final class ClassStrings {
    private ClassStrings() {
    }

    /** Every CONSTANT_Utf8 of the class file (empty if it is not one). */
    static Set<String> of(byte[] classFile) {
        Set<String> out = new LinkedHashSet<>();
        try (DataInputStream in = new DataInputStream(new ByteArrayInputStream(classFile))) {
            if (in.readInt() != 0xCAFEBABE) {
                return out;
            }
            in.readUnsignedShort();
            in.readUnsignedShort();
            int count = in.readUnsignedShort();
            for (int i = 1; i < count; i++) {
                int tag = in.readUnsignedByte();
                switch (tag) {
                    case 1 -> out.add(in.readUTF());
                    case 3, 4, 9, 10, 11, 12, 17, 18 -> in.skipNBytes(4);
                    case 5, 6 -> {
                        in.skipNBytes(8);
                        i++; // takes two entries
                    }
                    case 7, 8, 16, 19, 20 -> in.skipNBytes(2);
                    case 15 -> in.skipNBytes(3);
                    default -> {
                        return out; // unknown tag: stop, keep what was read
                    }
                }
            }
        } catch (IOException e) {
            // truncated: what was read stands
        }
        return out;
    }
}
