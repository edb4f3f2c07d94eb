package dev.strahl.cli;

import org.joml.Vector3d;
import picocli.CommandLine;

/** Parses "x,y,z" into a vector for options such as --look-from. */
final class Vectors implements CommandLine.ITypeConverter<Vector3d> {
    @Override
    public Vector3d convert(String value) {
        String[] parts = value.split(",", -1);
        if (parts.length != 3) {
            throw new CommandLine.TypeConversionException("expected x,y,z but got '" + value + "'");
        }
        double[] v = new double[3];
        for (int i = 0; i < 3; i++) {
            try {
                v[i] = Double.parseDouble(parts[i].trim());
            } catch (NumberFormatException e) {
                throw new CommandLine.TypeConversionException("'" + parts[i].trim() + "' in '" + value + "' is not a number");
            }
            if (!Double.isFinite(v[i])) {
                throw new CommandLine.TypeConversionException("'" + value + "' must be finite");
            }
        }
        return new Vector3d(v[0], v[1], v[2]);
    }
}
