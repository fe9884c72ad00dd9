package raylab.study;

/** One measured experiment of the study: writes its section, plots and conclusions. */
interface Experiment {
    /** Short name for {@code --only}. */
    String name();

    /** One line for {@code --help} and the log. */
    String title();

    void run(Study study) throws Exception;
}
