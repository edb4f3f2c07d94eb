package dev.strahl.integrator;

/**
 * The photon mapper's parameters.
 *
 * @param photonsPerIteration photons emitted from the lights in each iteration (= each sample per
 *                            pixel), 1 .. {@value #MAX_PHOTONS}
 * @param initialRadius       gather radius of the first iteration, in scene units; 0 chooses
 *                            {@value #DEFAULT_RADIUS_FRACTION} of the scene's bounding-box diagonal
 */
public record PhotonParameters(int photonsPerIteration, double initialRadius) {
    /** Photons per iteration unless the user says otherwise. */
    public static final int DEFAULT_PHOTONS = 100_000;
    /** Most photons per iteration accepted: stored photons take 40 bytes each, twice during a build. */
    public static final int MAX_PHOTONS = 10_000_000;
    /** The automatic initial radius as a fraction of the bounding-box diagonal. */
    public static final double DEFAULT_RADIUS_FRACTION = 0.01;

    public PhotonParameters {
        if (photonsPerIteration < 1 || photonsPerIteration > MAX_PHOTONS) {
            throw new IllegalArgumentException("photons per iteration must lie in 1 .. " + MAX_PHOTONS + ", got " + photonsPerIteration);
        }
        if (!(initialRadius >= 0) || !Double.isFinite(initialRadius)) {
            throw new IllegalArgumentException("photon radius must be a finite number >= 0 (0 = automatic), got " + initialRadius);
        }
    }

    /** {@value #DEFAULT_PHOTONS} photons per iteration, automatic radius. */
    public static PhotonParameters defaults() {
        return new PhotonParameters(DEFAULT_PHOTONS, 0);
    }
}
