package raylab.mesh;

import raylab.material.Material;
import raylab.surface.BvhNodes;
import raylab.surface.Mesh;
import raylab.surface.PackedEngine;

/**
 * Provides {@link PackedTriangles} as this build's {@link PackedEngine} (listed in
 * {@code META-INF/services/raylab.surface.PackedEngine}; instructor-only, as the engine).
 */
public final class PackedTrianglesProvider implements PackedEngine {
    @Override
    public Mesh.Engine of(Mesh mesh, double[] tri, BvhNodes tree, Material material) {
        return new PackedTriangles(mesh, tri, tree, material);
    }
}
