package raylab.render;

/** What the renderer draws: the full shading, or one ingredient of it for debugging. */
public enum Mode {
    /** L = ka·Ia + Σ [diffuse + specular], as the scene and the plan say. */
    FULL,
    /** The unit normal facing the viewer, as colour (n + 1) / 2. */
    NORMALS,
    /** Distance to the hit, white near the camera to black far away. */
    DEPTH,
    /** Only the diffuse terms, with shadows. */
    DIFFUSE,
    /** Only the specular terms, with shadows. */
    SPECULAR,
    /** White where a point sees every light, black where all are blocked, grey between. */
    SHADOWS
}
