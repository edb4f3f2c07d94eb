package dev.strahl.medium;

/**
 * A coarse grid over a {@link DensityGrid}: for each brick of {@value #BRICK}³ voxels, the largest
 * value a trilinear lookup inside the brick can return (the maximum over the brick's voxels and the
 * ring of voxels around it that lookups near its faces read). Delta and ratio tracking use it as a
 * majorant that is tight where the grid is sparse: in a brick of empty voxels it is 0, and a ray
 * crosses it without a single tentative collision.
 */
final class MajorantGrid {
    static final int BRICK = 8;

    final int nx, ny, nz;
    private final float[] max;

    MajorantGrid(DensityGrid grid) {
        nx = (grid.sizeX() + BRICK - 1) / BRICK;
        ny = (grid.sizeY() + BRICK - 1) / BRICK;
        nz = (grid.sizeZ() + BRICK - 1) / BRICK;
        max = new float[nx * ny * nz];
        for (int k = 0; k < grid.sizeZ(); k++) {
            for (int j = 0; j < grid.sizeY(); j++) {
                for (int i = 0; i < grid.sizeX(); i++) {
                    float v = (float) grid.voxel(i, j, k);
                    // voxel i is read by lookups in the bricks of voxels i - 1 .. i + 1 (trilinear, half a voxel each way)
                    for (int bk = brick(k - 1); bk <= brick(k + 1) && bk < nz; bk++) {
                        for (int bj = brick(j - 1); bj <= brick(j + 1) && bj < ny; bj++) {
                            for (int bi = brick(i - 1); bi <= brick(i + 1) && bi < nx; bi++) {
                                int at = (bk * ny + bj) * nx + bi;
                                max[at] = Math.max(max[at], v);
                            }
                        }
                    }
                }
            }
        }
    }

    private static int brick(int voxel) {
        return Math.max(voxel, 0) / BRICK;
    }

    /** The majorant (unscaled) of brick (i, j, k). */
    double max(int i, int j, int k) {
        return max[(k * ny + j) * nx + i];
    }
}
