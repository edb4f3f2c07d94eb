/**
 * Textures: a BSDF parameter that varies over a surface, looked up at the shading point's texture
 * coordinates (u, v) when the BSDF is evaluated or sampled (Mitsuba's way: BSDFs stay immutable and
 * shared by all threads; nothing is allocated per lookup).
 *
 * <p><b>Coordinates.</b> (0, 0) is the image's bottom-left corner and (1, 1) its top-right one, as
 * in OBJ files; {@link Bitmap} stores rows from the bottom up so that v = 0 is row 0. A texel's
 * centre is at ((x + ½)/w, (y + ½)/h). A {@link UvTransform} (scale, offset, rotation) is applied
 * first, then the {@link Wrap} mode brings the coordinates back into the image.
 *
 * <p><b>Values.</b> A colour texture gives linear RGB (8- and 16-bit images decoded from sRGB by
 * table when they are loaded, unless they are stored linearly); a scalar texture gives one
 * {@link Channel} of a linear image. A {@link ScaledTexture} multiplies either by a factor (glTF's
 * factor × texture).
 *
 * <p>This package sits below {@code material} (BSDFs hold textures) and {@code geometry} (alpha
 * cut-outs are decided during traversal); it reads no files: {@code dev.strahl.scene} loads them
 * with the readers of {@code dev.strahl.codec} and hands the pixels over as a {@link Bitmap}.
 */
package dev.strahl.texture;
