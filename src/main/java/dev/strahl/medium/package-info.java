/**
 * Participating media: what fills the space between surfaces (fog, the inside of tinted glass, wax,
 * smoke), and the Henyey–Greenstein phase function that scatters light inside them.
 *
 * <p>A medium is described by its extinction σt (per scene unit; the probability per unit length
 * that light travelling through it is absorbed or scattered) and its single-scattering albedo
 * α = σs/σt (the part of the extinction that scatters rather than absorbs). Light that crosses a
 * distance d of a homogeneous medium keeps the fraction T = e^(−σt·d) (Beer–Lambert), per channel.
 *
 * <p>Directions follow the surfaces' convention: unit vectors pointing <em>away</em> from the
 * scattering point, {@code wo} towards the previous path vertex (the camera side), {@code wi}
 * towards the next one (the light side). So the light's direction of travel turns from −wo to wi,
 * and the scattering angle θ has cosθ = −wo·wi (forward scattering: wi = −wo, cosθ = 1).
 *
 * <p>Sampling routines take their uniform numbers from the caller. Where the number of draws
 * depends on the medium (delta and ratio tracking through a grid), they draw from a
 * {@link TrackingRandom} the caller seeds from its sampler, so that the caller's own sequence of
 * dimensions stays the same whatever the medium does. Nothing here allocates per ray.
 */
package dev.strahl.medium;
