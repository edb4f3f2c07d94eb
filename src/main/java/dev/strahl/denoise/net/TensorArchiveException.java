package dev.strahl.denoise.net;

import java.io.IOException;

/** A tensor archive that cannot be used: one line naming the file and what is wrong with it. */
final class TensorArchiveException extends IOException {
    private static final long serialVersionUID = 1L;

    TensorArchiveException(String message) {
        super(message);
    }
}
