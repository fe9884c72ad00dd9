package raylab.study;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.DoubleFunction;

/**
 * A recommendation computed from measured numbers by one stated rule ({@link #RULE}), never
 * written in advance: feed it reversed numbers and it recommends the other method; feed it
 * costs whose intervals overlap and it says the race is too close to call.
 */
final class Verdict {
    /** The decision rule, as printed in the report. */
    static final String RULE = "Among the methods whose error is within the tolerance the task needs, recommend the"
            + " cheapest, provided the bootstrap 95% interval of its cost ratio to the next cheapest lies wholly below"
            + " 1/(1 + noise), where noise is the relative spread (interquartile range over median) of a calibration loop"
            + " timed in the same turns: on a quiet machine the interval must exclude 1, on a busy one the difference must"
            + " also exceed the machine's own variation. Otherwise the verdict is \"too close to call on this machine\"."
            + " If only one method is"
            + " within the tolerance, recommend it whatever it costs. If none is, recommend none and name the most"
            + " accurate.";

    /** The phrase used when costs cannot be told apart. */
    static final String TOO_CLOSE = "too close to call on this machine";

    enum Kind {
        /** Exactly one method is within the tolerance. */
        ONLY_ACCURATE,
        /** Several are; the cheapest is cheaper beyond the interval. */
        CHEAPEST,
        /** Several are; the two cheapest cannot be told apart. */
        TOO_CLOSE,
        /** None is. */
        NONE_ACCURATE
    }

    /** One competing method: its name, its error (smaller is better) and its measured cost. */
    record Option(String name, double error, Timing.Stats cost) {
    }

    final Kind kind;
    /** The recommended method (ONLY_ACCURATE, CHEAPEST), or the cheaper of the two (TOO_CLOSE), or the most accurate (NONE_ACCURATE). */
    final Option winner;
    /** The method compared with: the next cheapest within tolerance, or (ONLY_ACCURATE) the cheapest other. Null if alone. */
    final Option other;
    /** cost(winner) / cost(other), with its interval; null when other is null. */
    final Timing.Ratio ratio;
    final double tolerance;
    final List<Option> options;

    private Verdict(Kind kind, Option winner, Option other, double tolerance, List<Option> options) {
        this.kind = kind;
        this.winner = winner;
        this.other = other;
        this.ratio = other == null ? null : Timing.ratio(winner.cost(), other.cost());
        this.tolerance = tolerance;
        this.options = List.copyOf(options);
    }

    /** Applies {@link #RULE} to the options. */
    static Verdict decide(List<Option> options, double tolerance) {
        List<Option> within = new ArrayList<>();
        for (Option o : options) {
            if (o.error() <= tolerance) {
                within.add(o);
            }
        }
        Comparator<Option> byCost = Comparator.comparingDouble(o -> o.cost().median());
        if (within.isEmpty()) {
            Option best = options.stream().min(Comparator.comparingDouble(Option::error)).orElseThrow();
            return new Verdict(Kind.NONE_ACCURATE, best, null, tolerance, options);
        }
        if (within.size() == 1) {
            Option only = within.get(0);
            Option cheapestOther = options.stream().filter(o -> o != only).min(byCost).orElse(null);
            return new Verdict(Kind.ONLY_ACCURATE, only, cheapestOther, tolerance, options);
        }
        within.sort(byCost);
        Option first = within.get(0);
        Option second = within.get(1);
        Timing.Ratio r = Timing.ratio(first.cost(), second.cost());
        double noise = Math.max(first.cost().noise(), second.cost().noise());
        return new Verdict(r.hi() < 1 / (1 + noise) ? Kind.CHEAPEST : Kind.TOO_CLOSE, first, second, tolerance, options);
    }

    /** The calibration spread while the compared costs were measured (0 without a comparison). */
    double noise() {
        return other == null ? 0 : Math.max(winner.cost().noise(), other.cost().noise());
    }

    /** Whether the machine was too busy while the compared costs were measured. */
    boolean busy() {
        return noise() > Timing.NOISY;
    }

    private String busyText() {
        return String.format(", within the machine's own variation (the calibration loop varied by %.0f%%)", 100 * noise());
    }

    /** The recommended method's name, or null when there is none (TOO_CLOSE, NONE_ACCURATE). */
    String recommended() {
        return kind == Kind.ONLY_ACCURATE || kind == Kind.CHEAPEST ? winner.name() : null;
    }

    /** Bold headline: "use X", "too close to call on this machine" or "no method is within the tolerance". */
    String headline() {
        switch (kind) {
            case ONLY_ACCURATE:
            case CHEAPEST:
                return "use " + winner.name();
            case TOO_CLOSE:
                return TOO_CLOSE + " (" + winner.name() + " or " + other.name() + ")";
            default:
                return "no method is within the tolerance";
        }
    }

    /**
     * The reasoning in one or two sentences, from the numbers: errors printed by {@code error},
     * the tolerance described by {@code toleranceText}, costs named by {@code costName}.
     */
    String reason(String errorName, DoubleFunction<String> error, String toleranceText, String costName) {
        StringBuilder sb = new StringBuilder();
        switch (kind) {
            case ONLY_ACCURATE:
                sb.append(winner.name()).append(" is the only method within the tolerance (").append(toleranceText)
                        .append("): ").append(errorName).append(' ').append(error.apply(winner.error()));
                for (Option o : options) {
                    if (o != winner) {
                        sb.append(", ").append(o.name()).append(' ').append(error.apply(o.error()));
                    }
                }
                sb.append('.');
                if (other != null) {
                    sb.append(" Its ").append(costName).append(" is ").append(ratio.format()).append(" that of ")
                            .append(other.name()).append(ratio.lo() > 1 + noise() ? ", the price of being right"
                                    : ratio.hi() < 1 / (1 + noise()) ? ": it is also cheaper"
                                    : busy() ? busyText() : ", not distinguishable on this machine")
                            .append('.');
                }
                break;
            case CHEAPEST:
                sb.append(winner.name()).append(" and ").append(other.name()).append(" are both within the tolerance (")
                        .append(toleranceText).append("), and ").append(winner.name()).append("'s ").append(costName)
                        .append(" is ").append(ratio.format()).append(" that of ").append(other.name())
                        .append(noise() > 0 ? String.format(", an interval wholly below 1/(1 + %.2f)", noise()) : ", wholly below 1")
                        .append('.');
                break;
            case TOO_CLOSE:
                sb.append(winner.name()).append(" and ").append(other.name()).append(" are both within the tolerance (")
                        .append(toleranceText).append("), and ").append(winner.name()).append("'s ").append(costName)
                        .append(" is ").append(ratio.format()).append(" that of ").append(other.name())
                        .append(busy() ? busyText() + "." : ": the interval reaches 1, so the measurement cannot tell them apart.");
                break;
            default:
                sb.append("No method is within the tolerance (").append(toleranceText).append("); the most accurate is ")
                        .append(winner.name()).append(" (").append(errorName).append(' ')
                        .append(error.apply(winner.error())).append(").");
        }
        return Character.toUpperCase(sb.charAt(0)) + sb.substring(1);
    }
}
