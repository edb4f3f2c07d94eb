package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/**
 * {@code render}'s teaching options (docs/experiments.md): what a first ray tracer did, to measure
 * what strahl does instead. {@code --accel} and {@code --schedule} change no bit of the image,
 * {@code --shadows off} does, and {@code --light-selection power} changes its noise.
 */
final class TeachingOptions extends ShadowsOption {

    @Option(names = "--accel", defaultValue = "bvh", paramLabel = "bvh|none", order = 1,
            description = "Teaching option: none tests every ray against every primitive (no BVH), to measure what the BVH buys; "
                    + "same image, many times slower (default: ${DEFAULT-VALUE}).")
    Accel accel;

    @Option(names = "--schedule", defaultValue = "tiles", paramLabel = "tiles|stripes", order = 2,
            description = "Teaching option: stripes gives each of n threads one horizontal stripe of the image instead of "
                    + "32x32 tiles taken by whichever thread is free; same image, threads wait more (default: ${DEFAULT-VALUE}).")
    Schedule schedule;

    @Option(names = "--light-selection", defaultValue = "tree", paramLabel = "tree|power", order = 4,
            description = "Teaching option: power picks the light of each shadow ray by its power alone instead of by what it gives "
                    + "the point (a light tree); same image, noisier where there are many lights (default: ${DEFAULT-VALUE}).")
    LightSelection lightSelection;

    /** The values of --light-selection. */
    enum LightSelection { TREE, POWER }

    /** The values of --accel. */
    enum Accel { BVH, NONE }

    /** The values of --schedule. */
    enum Schedule { TILES, STRIPES }

    @Override
    RenderSettings applyTo(RenderSettings base) {
        return super.applyTo(base).withBruteForce(accel == Accel.NONE).withStripes(schedule == Schedule.STRIPES)
                .withLightTree(lightSelection != LightSelection.POWER);
    }
}
