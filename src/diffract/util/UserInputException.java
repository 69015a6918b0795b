package diffract.util;

/**
 * A problem with what the user gave us (a file, a number, a scene): the message is one line that names the
 * problem and, where we can, the fix. The CLI prints it without a stack trace and exits with code 2.
 */
public class UserInputException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public UserInputException(String message) {
        super(message);
    }

    public UserInputException(String message, Throwable cause) {
        super(message, cause);
    }
}
