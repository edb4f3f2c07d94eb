package dev.strahl.render;

/**
 * How the render threads share the image in each pass. Every pixel's samples depend on the
 * seed, the pixel and the sample index alone, so both give the same image bit for bit; they
 * differ in how long threads wait for each other ({@link RenderStats#threadIdleSeconds()}).
 */
public enum Schedule {
    /** 32×32-pixel tiles taken one after another from a shared counter by whichever thread is free: the default. */
    TILES,
    /**
     * Teaching option: the image cut into n horizontal stripes of equal height, one for each of
     * the n threads, as in a first multithreaded ray tracer; a thread whose stripe is cheap waits
     * for the others at the end of every pass.
     */
    STRIPES
}
