package raylab.scene;

/**
 * Effects a scene switches on or off explicitly. A null entry means "automatic": the renderer
 * decides from the scene's content whether the effect is needed (see the render plan).
 *
 * @param shadows      shadow rays
 * @param specular     the Blinn-Phong specular term
 * @param ambient      the ambient term ka·Ia
 * @param acceleration the bounding volume hierarchy
 */
public record Effects(Boolean shadows, Boolean specular, Boolean ambient, Boolean acceleration) {
    /** Every effect automatic. */
    public static final Effects AUTO = new Effects(null, null, null, null);
}
