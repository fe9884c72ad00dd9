package raylab.scene;

/** Where the samples of a pixel go when a scene asks for more than one per pixel. */
public enum Sampler {
    /** Independent uniform positions in the pixel. */
    RANDOM,
    /** One uniform position in each cell of a k×k grid over the pixel (k² samples). */
    STRATIFIED
}
