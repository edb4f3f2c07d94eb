package dev.strahl.codec.exr;

/**
 * Compressed pixel data that do not decode; {@link ExrReader} adds the file, the chunk and its byte
 * offset and reports it as an {@link dev.strahl.codec.ImageFormatException}.
 */
final class CorruptDataException extends Exception {
    private static final long serialVersionUID = 1L;

    CorruptDataException(String message) {
        super(message, null, false, false);   // a message for the user; no stack trace needed
    }
}
