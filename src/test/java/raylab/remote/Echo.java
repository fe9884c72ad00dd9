package raylab.remote;

/** Test support served by a student process: gives back what it got, or misbehaves on purpose. */
public final class Echo {
    private Echo() {
    }

    public static Object echo(Object o) {
        return o;
    }

    public static double boom(Object o) {
        String s = o == null ? null : "x";
        return s.length(); // NullPointerException for null
    }

    public static boolean hang(Object o) {
        long i = 0;
        while (o != Echo.class) {
            i++;
        }
        return i > 0;
    }

    public static int shout(Object o) {
        System.out.println("student says " + o);
        return 7;
    }

    /** Sleeps {@code ms} milliseconds (a number), then gives it back: a call that takes wall time and no CPU. */
    public static Object nap(Object ms) throws InterruptedException {
        Thread.sleep(((Number) ms).longValue());
        return ms;
    }

    /** Computes {@code millions} million square roots (a number; a fixed amount of CPU work), then gives the count back. */
    public static Object work(Object millions) {
        long n = ((Number) millions).longValue() * 1_000_000L;
        double x = 1;
        for (long i = 0; i < n; i++) {
            x = Math.sqrt(x + i);
        }
        return x > 0 ? millions : null;
    }

    /** Bytes that look like a frame (a RETURN of 4 bytes to conversation 1) and a line of text. */
    static final byte[] NOISE = {0, 0, 0, 9, 4, 0, 0, 0, 1, 0, 0, 0, 42, 'n', 'o', 'i', 's', 'e', '\n'};

    /** Writes to file descriptors 1 and 2 directly, around System.out, and asks for a GC (logged). */
    public static int raw(Object o) throws java.io.IOException {
        java.io.FileOutputStream fd1 = new java.io.FileOutputStream(java.io.FileDescriptor.out);
        java.io.FileOutputStream fd2 = new java.io.FileOutputStream(java.io.FileDescriptor.err);
        fd1.write(NOISE);
        fd1.flush();
        System.out.println("said " + o);
        fd2.write(NOISE);
        fd2.flush();
        System.gc();
        return 8;
    }
}
