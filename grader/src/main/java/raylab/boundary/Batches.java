package raylab.boundary;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import raylab.material.Material;
import raylab.ray.IntersectionRecord;
import raylab.remote.StudentServer;
import raylab.remote.Wire;
import raylab.shading.ShadingPoint;

/**
 * Many calls in one frame each way ({@link Wire#MULTI}): what a batched render and a single
 * {@link StudentProcess#call} send. A question to the grader's surfaces or materials that was not
 * answered in advance comes back with its call, which is sent again with the grader's answer (up
 * to {@link #DEFERRED_ROUNDS} frames); other questions, and all after those frames, are answered
 * as they come. Each call's outcome is set on it, exactly as if every question had been answered
 * as it came: a question's answer is the grader's own, whenever it is given.
 *
 * <p>The frames go through a {@link Link}, the RPC client of one {@link StudentProcess}, which
 * holds its lock while a batch runs.
 */
public final class Batches {
    /**
     * Frames of one batch in which questions to the grader's surfaces and materials that were
     * not answered in advance come back with the calls (answered, they go out again with the
     * calls that asked them); after them, such questions are callbacks.
     */
    static final int DEFERRED_ROUNDS = 4;

    /**
     * One call of a batch: the method, its target and arguments (records as they are before the
     * call; not changed by it), the callbacks it is expected to ask with their answers (the
     * grader's own, never a prediction); and after the call its result or exception and the
     * record arguments as the student's code left them.
     */
    public static final class Call {
        final String cls;
        final String name;
        final Object target;
        final Object[] args;
        final List<Answered> answers;
        Object result;
        RuntimeException thrown;
        /** After the call: each record argument as the student's code left it (null for other arguments). */
        IntersectionRecord[] after;
        /** The grader's answers to questions the call sent back: [question, answer] payloads; null: none. */
        List<byte[][]> truths;
        /** Whether its questions are asked as callbacks (one of them could not be answered later). */
        boolean live;

        public Call(String cls, String name, Object target, Object[] args, List<Answered> answers) {
            this.cls = cls;
            this.name = name;
            this.target = target;
            this.args = args;
            this.answers = answers;
        }

        public Object result() {
            return result;
        }

        public RuntimeException thrown() {
            return thrown;
        }

        public IntersectionRecord[] after() {
            return after;
        }
    }

    /**
     * A callback answered in advance: the grader's object asked, the operation, the arguments (a
     * record as it is before the question), the answer and the record arguments after it.
     */
    public record Answered(Object target, byte op, Object[] args, Object result, Object[] after) {
    }

    /** What a batch needs of the RPC client that sends it. */
    interface Link {
        /** Run before each frame of an outermost call. */
        void checkpoint();

        /** The id of a method in the student process, declared there on first use. */
        int method(String cls, String name, int arity) throws IOException;

        /** The number of a grader's object for the current call. */
        int ephemeral(Object o);

        /** Values as the grader sends them. */
        Wire.Refs refs();

        /** The grader's objects as the student process writes them back in a question. */
        Wire.Refs asStudent();

        /**
         * Sends {@code payload} as a frame of {@code type}; returns the reply of {@code replyType},
         * callbacks answered meanwhile.
         */
        Wire.In exchange(byte type, Wire.Out payload, byte replyType) throws IOException;

        /** An exception in a reply: class, message, frames. */
        RuntimeException throwable(Wire.In in) throws IOException;

        /** The student's captured output. */
        void output(String s);

        /** The CB_RETURN payload answering a question sent back, or null if the grader's object could not answer it. */
        byte[] answerLater(byte[] question) throws IOException;
    }

    private final Link link;
    /** A frame's payload, reused. */
    private final Wire.Out buf = new Wire.Out();
    private long multiBytes;
    private long deferredQuestions;

    Batches(Link link) {
        this.link = link;
    }

    /** Bytes of MULTI frames sent and received, for measurements. */
    long multiBytes() {
        return multiBytes;
    }

    /** Questions answered after their call came back, for measurements. */
    long deferredQuestions() {
        return deferredQuestions;
    }

    /** Makes the calls of {@code batch}, setting each one's outcome on it. */
    void run(List<Call> batch) throws IOException {
        List<Call> open = batch;
        for (int round = 0; !open.isEmpty(); round++) {
            open = round(open, round < DEFERRED_ROUNDS);
        }
    }

    /**
     * Whether argument {@code b} of a call in a MULTI frame goes as {@link Wire#AS_BEFORE} after
     * {@code a}, the previous call's at the same place: a ray or a record equal bit for bit, or
     * the same object (a value, a light, or an object of the grader's or the student's) except a
     * shading point, which holds the answers of its own call.
     */
    private static boolean asBefore(Object a, Object b) {
        if (a == b) {
            return !(b instanceof ShadingPoint) && !(b instanceof IntersectionRecord);
        }
        return Wire.asBefore(a, b);
    }

    /** One MULTI frame each way; returns the calls sent back with questions, now answered. */
    private List<Call> round(List<Call> batch, boolean defer) throws IOException {
        link.checkpoint();
        writeRequest(batch, defer);
        Wire.In in = link.exchange(Wire.MULTI, buf, Wire.MULTI_RETURN);
        multiBytes += buf.size() + in.remaining();
        int n = in.readInt();
        if (n != batch.size()) {
            throw new Wire.ProtocolException("answered " + n + " of " + batch.size() + " calls");
        }
        List<Call> again = new ArrayList<>();
        List<List<byte[]>> asked = new ArrayList<>();
        for (Call c : batch) {
            byte status = in.readByte();
            if (status == 2) {
                int k = in.readInt();
                if (!defer || c.live || k < 1 || k > StudentServer.MAX_DEFERRED) {
                    throw new Wire.ProtocolException("questions sent back where none may be");
                }
                List<byte[]> questions = new ArrayList<>(k);
                for (int i = 0; i < k; i++) {
                    questions.add(in.readBytes());
                }
                again.add(c);
                asked.add(questions);
                continue;
            }
            if (status == 0) {
                c.result = Wire.readValue(in, link.refs());
                c.after = recordsAfter(in, c.args);
            } else if (status == 1) {
                c.thrown = link.throwable(in);
            } else {
                throw new Wire.ProtocolException("bad call status " + status);
            }
            // Answers are reported used only below the count of predicted ones, which is 0: a
            // report is a broken or forged reply, and nothing the reply says about itself counts.
            if (in.readInt() != 0) {
                throw new Wire.ProtocolException("reported answers used where none were predicted");
            }
        }
        link.output(in.readString());
        // Answered only now that the whole reply is read: an answer may itself call the student process.
        for (int i = 0; i < again.size(); i++) {
            Call c = again.get(i);
            for (byte[] question : asked.get(i)) {
                byte[] answer = link.answerLater(question);
                deferredQuestions++;
                if (answer == null) {
                    c.live = true; // asked again as a callback, which reports what went wrong
                    continue;
                }
                if (c.truths == null) {
                    c.truths = new ArrayList<>();
                }
                if (c.truths.stream().noneMatch(t -> Arrays.equals(t[0], question))) {
                    c.truths.add(new byte[][] {question, answer});
                }
            }
        }
        return again;
    }

    /** The MULTI payload of {@code batch} into {@link #buf}. */
    private void writeRequest(List<Call> batch, boolean defer) throws IOException {
        Wire.Refs refs = link.refs();
        buf.reset();
        buf.writeInt(batch.size());
        Wire.Out q = new Wire.Out();
        Wire.Out a = new Wire.Out();
        Object[] previous = new Object[0];
        for (Call c : batch) {
            buf.writeBoolean(defer && !c.live);
            buf.writeInt(link.method(c.cls, c.name, c.args.length));
            Wire.writeValue(buf, c.target, refs);
            buf.writeInt(c.args.length);
            for (int j = 0; j < c.args.length; j++) {
                // The ray of a pixel goes to every surface, and a record a surface missed to the next.
                if (j < previous.length && asBefore(previous[j], c.args[j])) {
                    buf.writeByte(Wire.AS_BEFORE);
                } else if (j < previous.length && previous[j] != c.args[j]
                        && previous[j] instanceof IntersectionRecord p && c.args[j] instanceof IntersectionRecord r
                        && Wire.sameButTests(p, r)) {
                    // The record a group passes from one surface to the next: only the count differs.
                    buf.writeByte(Wire.AS_BEFORE_TESTS);
                    buf.writeLong(r.tests);
                } else {
                    Wire.writeValue(buf, c.args[j], refs);
                }
            }
            previous = c.args;
            int truths = c.truths == null ? 0 : c.truths.size();
            // No answer given in advance is a prediction: every one is the grader's own, so none
            // is to be reported as used (grader/README.md, "What crosses the boundary").
            buf.writeInt(0);
            buf.writeInt(c.answers.size() + truths);
            for (Answered an : c.answers) {
                q.reset();
                q.writeInt(link.ephemeral(an.target()));
                q.writeByte(an.op());
                q.writeInt(an.args().length);
                for (Object x : an.args()) {
                    Wire.writeValue(q, x, link.asStudent());
                }
                buf.writeBytes(q);
                a.reset();
                Wire.writeValue(a, an.result(), refs);
                for (Object x : an.after()) {
                    if (x instanceof IntersectionRecord r) {
                        Wire.writeRecord(a, r, refs);
                    }
                }
                buf.writeBytes(a);
            }
            for (int t = 0; t < truths; t++) {
                buf.writeBytes(c.truths.get(t)[0]);
                buf.writeBytes(c.truths.get(t)[1]);
            }
        }
    }

    /** Each record argument as the student's code left it, from a returned call's reply. */
    private IntersectionRecord[] recordsAfter(Wire.In in, Object[] args) throws IOException {
        IntersectionRecord[] after = new IntersectionRecord[args.length];
        for (int j = 0; j < args.length; j++) {
            if (args[j] instanceof IntersectionRecord r) {
                byte tag = in.readByte();
                // A record left as it was sent is that record (never changed), its
                // material the surface's as for a record read back.
                after[j] = r;
                if (tag == Wire.RECORD) {
                    after[j] = Wire.copyRecord(r);
                    Wire.readRecordInto(in, after[j], link.refs());
                } else if (tag != Wire.AS_BEFORE) {
                    throw new Wire.ProtocolException("bad record tag " + tag);
                } else {
                    Material m = r.surface == null ? null : r.surface.material();
                    if (r.material != m) {
                        after[j] = Wire.copyRecord(r);
                        after[j].material = m;
                    }
                }
            }
        }
        return after;
    }
}
