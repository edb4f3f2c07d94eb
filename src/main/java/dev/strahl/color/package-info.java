/**
 * What the renderer does with colours, right above the API's colour value ({@code dev.strahl.image.Rgb}):
 * {@link dev.strahl.color.MutableRgb}, the per-thread accumulator of the hot loops;
 * {@link dev.strahl.color.Srgb}, the sRGB transfer function both ways (texture images decoded,
 * display and PNG values encoded); and {@link dev.strahl.color.DisplayEncoding}, linear radiance to
 * 8-bit display pixels with the tone curves that {@code dev.strahl.image.ToneMapping} names.
 */
package dev.strahl.color;
