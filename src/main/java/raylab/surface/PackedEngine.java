package raylab.surface;

import raylab.material.Material;

/**
 * A build's packed mesh engine: a service, listed in
 * {@code META-INF/services/raylab.surface.PackedEngine}. The instructor's build provides one (the
 * mesh engine module, {@code raylab.mesh.PackedTrianglesProvider}); the starter has none, so its
 * meshes always use the student kernel. {@link Mesh} uses a provider only when it, {@code Mesh}
 * and {@link Triangle} come from one code source.
 */
public interface PackedEngine {
    /**
     * The engine of one mesh: its triangles {@code tri} in the tree's leaf order (a, b, c: nine
     * numbers each), its tree and its material.
     */
    Mesh.Engine of(Mesh mesh, double[] tri, BvhNodes tree, Material material);
}
