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
}
