package raylab.render;

/** Counters of one render; each thread keeps its own, summed at the end. */
public final class RenderStats {
    public long eyeRays;
    public long shadowRays;
    public long shadowRaysBlocked;
    public long intersectionTests;
    public long specularEvaluations;
    public long nonFinitePixels;

    /** Adds another thread's counts to these. */
    public void add(RenderStats o) {
        eyeRays += o.eyeRays;
        shadowRays += o.shadowRays;
        shadowRaysBlocked += o.shadowRaysBlocked;
        intersectionTests += o.intersectionTests;
        specularEvaluations += o.specularEvaluations;
        nonFinitePixels += o.nonFinitePixels;
    }
}
