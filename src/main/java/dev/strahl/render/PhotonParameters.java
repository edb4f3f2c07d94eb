package dev.strahl.render;

/**
 * The photon mapper's parameters.
 *
 * @param photonsPerIteration photons emitted from the lights in each iteration (= each sample per
 *                            pixel), 1 .. {@value #MAX_PHOTONS}
 * @param initialRadius       gather radius of the first iteration, in scene units; 0 chooses
 *                            1/100 of the scene's bounding-box diagonal
 */
public record PhotonParameters(int photonsPerIteration, double initialRadius) {
    /** Photons per iteration unless the user says otherwise. */
    public static final int DEFAULT_PHOTONS = 100_000;
    /** Most photons per iteration accepted: stored photons take 40 bytes each, twice during a build. */
    public static final int MAX_PHOTONS = 10_000_000;

    /**
     * Checks both values; the message names the one that is out of range.
     *
     * @param photonsPerIteration photons per iteration, 1 .. {@value #MAX_PHOTONS}
     * @param initialRadius       the first iteration's gather radius, finite and &gt;= 0; 0 = automatic
     */
    public PhotonParameters {
        if (photonsPerIteration < 1 || photonsPerIteration > MAX_PHOTONS) {
            throw new IllegalArgumentException("photons per iteration must lie in 1 .. " + MAX_PHOTONS + ", got " + photonsPerIteration);
        }
        if (!(initialRadius >= 0) || !Double.isFinite(initialRadius)) {
            throw new IllegalArgumentException("photon radius must be a finite number >= 0 (0 = automatic), got " + initialRadius);
        }
    }

    /**
     * {@value #DEFAULT_PHOTONS} photons per iteration, automatic radius.
     *
     * @return the defaults
     */
    public static PhotonParameters defaults() {
        return new PhotonParameters(DEFAULT_PHOTONS, 0);
    }
}
