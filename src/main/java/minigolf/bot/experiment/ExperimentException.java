package minigolf.bot.experiment;

/**
 * A problem with the experiment's input or files that the user can fix (a bad shard, a folder
 * written by another experiment, a missing run): the command line prints the message as one line.
 */
public final class ExperimentException extends RuntimeException {
    public ExperimentException(String message) {
        super(message);
    }
}
