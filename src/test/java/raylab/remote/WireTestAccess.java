package raylab.remote;

/** The special doubles of {@link WireTest}, for tests in other packages. */
public final class WireTestAccess {
    private WireTestAccess() {
    }

    public static double[] special() {
        return WireTest.SPECIAL.clone();
    }
}
