package raylab.boundary;

/**
 * The last few graded methods asked for, found by the identity of their class and method names
 * (the stand-ins' string constants) and their arity: a render asks for the same two or three
 * again and again, and looking them up by a built string key would cost more than the call.
 *
 * @param <T> what is kept per method
 */
final class RecentMethods<T> {
    private static final int SIZE = 4;
    private final String[] classes = new String[SIZE];
    private final String[] names = new String[SIZE];
    private final int[] arities = new int[SIZE];
    private final Object[] values = new Object[SIZE];
    private int next;

    /** The value kept for {@code cls.name} with {@code arity} parameters, or null. */
    @SuppressWarnings("unchecked")
    T get(String cls, String name, int arity) {
        for (int i = 0; i < SIZE; i++) {
            if (names[i] == name && classes[i] == cls && arities[i] == arity) {
                return (T) values[i];
            }
        }
        return null;
    }

    /** Keeps {@code value} in place of the oldest. */
    void put(String cls, String name, int arity, T value) {
        int i = next;
        next = (next + 1) % SIZE;
        classes[i] = cls;
        names[i] = name;
        arities[i] = arity;
        values[i] = value;
    }

    /** Forgets everything. */
    void clear() {
        java.util.Arrays.fill(classes, null);
        java.util.Arrays.fill(names, null);
        java.util.Arrays.fill(values, null);
    }
}
