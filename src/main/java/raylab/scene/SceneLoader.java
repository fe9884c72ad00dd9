package raylab.scene;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import raylab.camera.Camera;
import raylab.camera.OrthographicCamera;
import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.material.NormalColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.scene.JsonTree.Kind;
import raylab.scene.JsonTree.Node;

/**
 * Reads scene files (JSON, see docs/scene-format.md and scenes/scene.schema.json).
 *
 * <p>Every problem is a {@link SceneException} whose message is one line:
 * <pre>
 *   file:line:column: $.json.path: what is wrong, the offending value, what is expected
 * </pre>
 * or {@code file: message} for problems without a place in the JSON (empty, unreadable or binary
 * files).
 *
 * <p>One parser for one format: its sections follow docs/scene-format.md in order, and every one
 * reports through the same one-line error.
 */
public final class SceneLoader {
    /** Largest image width and height. */
    public static final int MAX_IMAGE_SIZE = 16384;
    /** Largest number of samples per pixel. */
    public static final int MAX_SAMPLES_PER_PIXEL = 4096;
    /** Largest scene file read, in bytes (64 MiB); a longer file is refused before parsing. */
    public static final long MAX_SCENE_BYTES = 64L << 20;

    /**
     * For each kind of JSON object, the keys the loader accepts, in documentation order. The kinds
     * are named as in the schema: "scene" is the top level, the others are the schema's $defs.
     */
    public static final Map<String, List<String>> ACCEPTED_KEYS;
    /** For each kind of JSON object, the keys it must have (lookAt|viewDirection aside). */
    public static final Map<String, List<String>> REQUIRED_KEYS;

    /** Surface "type" values and their kinds: every {@link SurfaceTypes#all() surface type}, each its own kind. */
    static final Map<String, String> SURFACE_TYPES = surfaceTypes();
    /** Material "type" values and their kinds. */
    static final Map<String, String> MATERIAL_TYPES = ordered(
            "lambertian", "lambertian", "blinnPhong", "blinnPhong", "flat", "flat",
            "normals", "normals");
    /** Camera "type" values and their kinds. */
    static final Map<String, String> CAMERA_TYPES = ordered(
            "perspective", "perspectiveCamera", "orthographic", "orthographicCamera");
    /** Light "type" values and their kinds. */
    static final Map<String, String> LIGHT_TYPES = ordered("point", "pointLight");

    /** How messages name each kind of object. */
    private static final Map<String, String> KIND_NAMES = ordered(
            "scene", "the top level of the scene",
            "image", "the image settings",
            "perspectiveCamera", "a perspective camera",
            "orthographicCamera", "an orthographic camera",
            "effects", "the effects",
            "lambertian", "a lambertian material",
            "blinnPhong", "a blinnPhong material",
            "flat", "a flat material",
            "normals", "a normals material",
            "pointLight", "a point light");
    /** How messages name each surface type ({@link SurfaceType#description}). */
    private static final Map<String, String> SURFACE_NAMES = new LinkedHashMap<>();

    static {
        Map<String, List<String>> a = new LinkedHashMap<>();
        Map<String, List<String>> r = new LinkedHashMap<>();
        a.put("scene", List.of("$schema", "image", "camera", "background", "ambient", "effects",
                "materials", "surfaces", "lights"));
        r.put("scene", List.of("image", "camera", "surfaces"));
        a.put("image", List.of("width", "height", "samplesPerPixel", "sampler"));
        r.put("image", List.of("width", "height"));
        a.put("perspectiveCamera", List.of("type", "eye", "lookAt", "viewDirection", "up", "fov"));
        r.put("perspectiveCamera", List.of("type", "eye", "up", "fov"));
        a.put("orthographicCamera",
                List.of("type", "eye", "lookAt", "viewDirection", "up", "viewHeight"));
        r.put("orthographicCamera", List.of("type", "eye", "up", "viewHeight"));
        a.put("effects", List.of("shadows", "specular", "ambient", "acceleration"));
        r.put("effects", List.of());
        a.put("lambertian", List.of("type", "kd", "ka"));
        r.put("lambertian", List.of("type", "kd"));
        a.put("blinnPhong", List.of("type", "kd", "ks", "p", "ka"));
        r.put("blinnPhong", List.of("type", "kd", "ks", "p"));
        a.put("flat", List.of("type", "color"));
        r.put("flat", List.of("type", "color"));
        a.put("normals", List.of("type"));
        r.put("normals", List.of("type"));
        for (SurfaceType t : SurfaceTypes.builtIn().values()) {
            a.put(t.type(), List.copyOf(t.keys()));
            r.put(t.type(), List.copyOf(t.requiredKeys()));
            SURFACE_NAMES.put(t.type(), t.description());
        }
        a.put("pointLight", List.of("type", "name", "position", "intensity", "shadows"));
        r.put("pointLight", List.of("type", "position", "intensity"));
        for (SurfaceType t : SurfaceTypes.extensions().values()) {
            a.put(t.type(), List.copyOf(t.keys()));
            r.put(t.type(), List.copyOf(t.requiredKeys()));
            SURFACE_NAMES.put(t.type(), t.description());
        }
        ACCEPTED_KEYS = java.util.Collections.unmodifiableMap(a);
        REQUIRED_KEYS = java.util.Collections.unmodifiableMap(r);
    }

    /** The scene file as shown in messages (control characters escaped). */
    private final String file;
    private final Path source;
    private final Path dir;

    private SceneLoader(Path file) {
        this.file = Display.path(file);
        this.source = file;
        this.dir = file.getParent();
    }

    /**
     * Loads and checks a scene; every problem is a SceneException with a one-line message. Only
     * a regular file (or a link to one) is read, and at most {@link #MAX_SCENE_BYTES} of it: a
     * directory, pipe, socket or device is refused before anything is read from it.
     */
    public static Scene load(Path file) throws SceneException {
        String name = Display.path(file);
        byte[] bytes;
        try {
            refuseSpecialFile(file, name, "a scene file");
            try (InputStream in = Files.newInputStream(file)) {
                bytes = in.readNBytes((int) MAX_SCENE_BYTES + 1);
            }
        } catch (NoSuchFileException e) {
            throw new SceneException(name + ": no such file");
        } catch (AccessDeniedException e) {
            throw new SceneException(name + ": permission denied");
        } catch (IOException e) {
            throw new SceneException(name + ": cannot read: " + Display.escape(JsonTree.firstLine(e.getMessage())));
        } catch (InvalidPathException e) {
            throw new SceneException(name + ": " + invalidPath(e));
        }
        if (bytes.length > MAX_SCENE_BYTES) {
            throw new SceneException(name + ": larger than " + (MAX_SCENE_BYTES >> 20)
                    + " MiB; a scene file is a small JSON text (put large meshes in OBJ files)");
        }
        return fromBytes(bytes, file);
    }

    /**
     * Checks and builds a scene from the bytes of a scene file as if it were read from {@code
     * pretendFile} (the same checks as {@link #load}, without the file system).
     */
    public static Scene fromBytes(byte[] bytes, Path pretendFile) throws SceneException {
        String name = Display.path(pretendFile);
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new SceneException(name + ": not a text file (NUL byte at offset " + i
                        + "); a scene file is UTF-8 JSON text");
            }
        }
        return parse(decodeUtf8(bytes, name), pretendFile);
    }

    /**
     * Refuses what exists but is not a regular file (or a link to one), before it is opened:
     * reading a FIFO would wait forever, a device such as /dev/zero never ends.
     *
     * @param what "a scene file", "an OBJ file", for the message
     */
    static void refuseSpecialFile(Path file, String name, String what) throws SceneException {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(file, BasicFileAttributes.class);
        } catch (IOException missingOrUnreadable) {
            return; // opening it gives the precise reason (no such file, permission denied)
        }
        if (a.isDirectory()) {
            throw new SceneException(name + ": is a directory, not " + what);
        }
        if (!a.isRegularFile()) {
            throw new SceneException(name + ": is " + specialKind(file) + ", not a regular file; "
                    + what + " must be a regular file");
        }
    }

    /** "a named pipe (FIFO)", "a character device", ... or "a special file". */
    private static String specialKind(Path file) {
        try {
            int mode = (Integer) Files.getAttribute(file, "unix:mode");
            switch (mode & 0170000) {
                case 0010000: return "a named pipe (FIFO)";
                case 0020000: return "a character device";
                case 0060000: return "a block device";
                case 0140000: return "a socket";
                default: return "a special file";
            }
        } catch (IOException | RuntimeException noUnixView) {
            return "a special file";
        }
    }

    private static boolean hasLoneSurrogate(String s) {
        for (int i = 0; i < s.length(); i++) {
            if (Character.isSurrogate(s.charAt(i)) && Display.needsEscape(s, i)) {
                return true;
            }
        }
        return false;
    }

    /** Why a path cannot be used, as a phrase (for InvalidPathException). */
    static String invalidPath(InvalidPathException e) {
        String reason = e.getReason() == null ? "" : e.getReason();
        if (reason.contains("Nul character")) {
            return "the file name contains a NUL character, which no file name can contain";
        }
        if (reason.contains("Malformed input") || reason.contains("unmappable")) {
            return "the file name cannot be encoded in this system's file-name encoding ("
                    + System.getProperty("sun.jnu.encoding", "unknown") + "), which lacks some of its"
                    + " characters; use ASCII names or a UTF-8 locale (LANG=C.UTF-8)";
        }
        return "not a usable file name: " + Display.escape(reason);
    }

    /**
     * Checks and builds a scene from JSON text as if it were read from {@code pretendFile}: error
     * messages start with it and mesh files are found relative to its directory.
     */
    public static Scene parse(String json, Path pretendFile) throws SceneException {
        String name = Display.path(pretendFile);
        if (json.startsWith("\uFEFF")) {
            json = json.substring(1); // a UTF-8 byte-order mark, as some Windows editors write
        }
        if (json.isEmpty()) {
            throw new SceneException(name + ": the file is empty (expected a JSON object with"
                    + " image, camera and surfaces)");
        }
        if (json.chars().allMatch(c -> c == ' ' || c == '\t' || c == '\n' || c == '\r')) {
            throw new SceneException(name + ": the file contains only whitespace (expected a JSON"
                    + " object with image, camera and surfaces)");
        }
        int nul = json.indexOf('\0');
        if (nul >= 0) {
            throw new SceneException(name + ": not a text file (NUL character at offset " + nul
                    + "); a scene file is UTF-8 JSON text");
        }
        Node root = JsonTree.read(json, name);
        return new SceneLoader(pretendFile).scene(root);
    }

    private static String decodeUtf8(byte[] bytes, String name) throws SceneException {
        CharsetDecoder dec = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length + 1);
        CoderResult res = dec.decode(in, out, true);
        if (res.isError()) {
            int at = in.position();
            throw new SceneException(name + ": not UTF-8 text (invalid byte 0x"
                    + String.format("%02X", bytes[at] & 0xFF) + " at offset " + at
                    + "); save the scene file as UTF-8");
        }
        dec.flush(out);
        out.flip();
        String s = out.toString();
        return s.startsWith("\uFEFF") ? s.substring(1) : s;
    }

    // ---------------------------------------------------------------- the scene

    private Scene scene(Node root) throws SceneException {
        if (root.kind != Kind.OBJECT) {
            throw fail(root, "a scene file must contain one JSON object {...}, got " + root.describe());
        }
        checkObject(root, "scene");
        Scene.Builder b = Scene.builder().source(source);

        Node image = object(root.get("image"));
        checkObject(image, "image");
        int width = integer(image.get("width"), 1, MAX_IMAGE_SIZE, "width");
        int height = integer(image.get("height"), 1, MAX_IMAGE_SIZE, "height");
        b.size(width, height);
        if (image.has("samplesPerPixel")) {
            b.samplesPerPixel(integer(image.get("samplesPerPixel"), 1, MAX_SAMPLES_PER_PIXEL,
                    "samplesPerPixel"));
        }
        b.sampler(image.has("sampler")
                ? (choice(image.get("sampler"), List.of("random", "stratified"), "sampler")
                        .equals("random") ? Sampler.RANDOM : Sampler.STRATIFIED)
                : Sampler.STRATIFIED);

        b.camera(camera(root.get("camera"), width, height));
        b.background(root.has("background") ? color(root.get("background")) : Color.BLACK);
        b.ambient(root.has("ambient") ? color(root.get("ambient")) : Color.BLACK);
        if (root.has("effects")) {
            b.effects(effects(root.get("effects")));
        }

        Map<String, Material> materials = new LinkedHashMap<>();
        if (root.has("materials")) {
            Node ms = object(root.get("materials"));
            for (Map.Entry<String, Node> e : ms.fields.entrySet()) {
                if (e.getKey().isBlank()) {
                    throw failKey(ms, e.getKey(), "a material name must not be empty");
                }
                materials.put(e.getKey(), material(e.getValue(), Display.escape(e.getKey())));
            }
        }

        Node surfaces = array(root.get("surfaces"));
        for (int i = 0; i < surfaces.items.size(); i++) {
            surface(b, surfaces.items.get(i), i, materials);
        }

        if (root.has("lights")) {
            Node lights = array(root.get("lights"));
            for (int i = 0; i < lights.items.size(); i++) {
                b.add(light(lights.items.get(i), i));
            }
        }
        return b.build();
    }

    private Effects effects(Node n) throws SceneException {
        object(n);
        checkObject(n, "effects");
        return new Effects(optionalBool(n, "shadows"), optionalBool(n, "specular"),
                optionalBool(n, "ambient"), optionalBool(n, "acceleration"));
    }

    private Boolean optionalBool(Node obj, String key) throws SceneException {
        return obj.has(key) ? bool(obj.get(key)) : null;
    }

    // ---------------------------------------------------------------- camera

    private Camera camera(Node n, int width, int height) throws SceneException {
        String kind = typed(n, CAMERA_TYPES, "camera");
        Vec3 eye = vec3(n.get("eye"));
        Vec3 up = vec3(n.get("up"));
        Vec3 view;
        if (n.has("lookAt") && n.has("viewDirection")) {
            throw fail(n.get("viewDirection"), "give either \"lookAt\" or \"viewDirection\", not both");
        } else if (n.has("lookAt")) {
            Vec3 lookAt = vec3(n.get("lookAt"));
            view = lookAt.minus(eye);
            if (!view.isFinite()) {
                throw fail(n.get("lookAt"), "the view direction lookAt - eye = " + fmt(view)
                        + " overflows (lookAt " + fmt(lookAt) + " and eye " + fmt(eye) + " are too far"
                        + " apart for their difference to be represented); bring them closer together");
            }
            if (view.lengthSquared() == 0) {
                throw fail(n.get("lookAt"), "lookAt equals eye " + fmt(eye)
                        + ", so there is no view direction; lookAt must differ from eye");
            }
        } else if (n.has("viewDirection")) {
            view = vec3(n.get("viewDirection"));
            if (view.lengthSquared() == 0) {
                throw fail(n.get("viewDirection"), "viewDirection must not be the zero vector");
            }
        } else {
            throw fail(n, "missing \"lookAt\" or \"viewDirection\": the camera needs one of them");
        }
        if (up.lengthSquared() == 0) {
            throw fail(n.get("up"), "up must not be the zero vector");
        }
        // Only their directions matter: scale both to a largest component of about 1 (exactly, by
        // a power of two) so that lengths, products and the normalisation cannot overflow.
        Vec3 givenView = view;
        Vec3 givenUp = up;
        view = direction(view);
        up = direction(up);
        if (!Camera.frameExists(view, up)) {
            throw fail(n.get("up"), "up " + fmt(givenUp) + " is parallel to the view direction "
                    + fmt(givenView) + "; choose an up vector that is not parallel to it");
        }
        if (kind.equals("perspectiveCamera")) {
            Node fovNode = n.get("fov");
            double fov = number(fovNode);
            if (!(fov > 0 && fov < 180)) {
                throw fail(fovNode, "fov must be between 0 and 180 degrees (exclusive), got "
                        + fovNode.text);
            }
            return new PerspectiveCamera(eye, view, up, fov, width, height);
        }
        double viewHeight = positive(n.get("viewHeight"), "viewHeight");
        return new OrthographicCamera(eye, view, up, viewHeight, width, height);
    }

    /** v scaled by a power of two so that its largest component lies in [1, 2). */
    private static Vec3 direction(Vec3 v) {
        int e = Math.getExponent(v.maxAbs());
        return new Vec3(Math.scalb(v.x, -e), Math.scalb(v.y, -e), Math.scalb(v.z, -e));
    }

    // ---------------------------------------------------------------- materials

    private Material material(Node n, String name) throws SceneException {
        String kind = typed(n, MATERIAL_TYPES, "material");
        switch (kind) {
            case "lambertian": {
                Color kd = color(n.get("kd"));
                Color ka = n.has("ka") ? color(n.get("ka")) : kd;
                return new Lambertian(kd, ka, name);
            }
            case "blinnPhong": {
                Color kd = color(n.get("kd"));
                Color ks = color(n.get("ks"));
                double p = number(n.get("p"));
                if (p < 0) {
                    throw fail(n.get("p"), "the exponent p must be at least 0, got " + n.get("p").text);
                }
                Color ka = n.has("ka") ? color(n.get("ka")) : kd;
                return new BlinnPhong(kd, ks, p, ka, name);
            }
            case "flat":
                return new FlatColor(color(n.get("color")), name);
            default:
                return new NormalColor(name);
        }
    }

    // ---------------------------------------------------------------- surfaces

    private void surface(Scene.Builder b, Node n, int index, Map<String, Material> materials)
            throws SceneException {
        String kind = typed(n, SURFACE_TYPES, "surface");
        String name = name(n, n.get("type").text + " #" + index);
        Material m = materialRef(n.get("material"), materials);
        b.add(SurfaceTypes.all().get(kind).build(fields(n), m, name));
    }

    /** A surface's keys, read with this loader's checks and messages ({@link SurfaceType.Fields}). */
    private SurfaceType.Fields fields(Node n) {
        return new SurfaceType.Fields() {
            @Override
            public boolean has(String key) {
                return n.has(key);
            }

            @Override
            public Vec3 vec3(String key) throws SceneException {
                return SceneLoader.this.vec3(present(key));
            }

            @Override
            public double number(String key) throws SceneException {
                return SceneLoader.this.number(present(key));
            }

            @Override
            public double positive(String key) throws SceneException {
                return SceneLoader.this.positive(present(key), key);
            }

            @Override
            public String string(String key) throws SceneException {
                return SceneLoader.this.string(present(key));
            }

            @Override
            public int count(String key) throws SceneException {
                return array(present(key)).items.size();
            }

            @Override
            public Vec3 vec3(String key, int index) throws SceneException {
                return SceneLoader.this.vec3(array(present(key)).items.get(index));
            }

            @Override
            public SurfaceType.ObjFile objFile(String key) throws SceneException {
                return obj(present(key));
            }

            @Override
            public SceneException fail(String key, String message) {
                return SceneLoader.this.fail(n.has(key) ? n.get(key) : n, message);
            }

            private Node present(String key) throws SceneException {
                if (!n.has(key)) {
                    throw SceneLoader.this.fail(n, "missing key " + JsonTree.quote(key) + " in " + kindName(n));
                }
                return n.get(key);
            }
        };
    }

    private static String kindName(Node n) {
        return kindNameOf(n.has("type") ? String.valueOf(n.get("type").text) : "");
    }

    /** How messages name a kind of object: "a perspective camera", or a surface type's description. */
    private static String kindNameOf(String kind) {
        String named = KIND_NAMES.get(kind);
        return named != null ? named : SURFACE_NAMES.getOrDefault(kind, "a " + kind);
    }

    /** The built-in surface types followed by those registered on the class path ({@link SurfaceTypes}). */
    private static Map<String, String> surfaceTypes() {
        Map<String, String> m = new LinkedHashMap<>();
        for (String t : SurfaceTypes.all().keySet()) {
            m.put(t, t);
        }
        return java.util.Collections.unmodifiableMap(m);
    }

    /** The OBJ file a surface's key names, relative to the scene file's directory, read and parsed. */
    private SurfaceType.ObjFile obj(Node fileNode) throws SceneException {
        String rel = string(fileNode);
        try {
            Path obj = dir == null ? Path.of(rel) : dir.resolve(rel);
            String display = Display.path(obj);
            refuseSpecialFile(obj, display, "an OBJ file");
            return new SurfaceType.ObjFile(display, ObjLoader.read(obj, display).triangleVertices());
        } catch (ObjLoader.ObjException e) {
            throw fail(fileNode, Display.escape(e.getMessage()));
        } catch (SceneException e) {
            throw fail(fileNode, e.getMessage());
        } catch (InvalidPathException e) {
            throw fail(fileNode, "cannot use " + JsonTree.quote(rel) + ": " + (hasLoneSurrogate(rel)
                    ? "the file name contains a lone surrogate (half of a UTF-16 pair), which no file"
                    + " name can contain" : invalidPath(e)));
        }
    }

    private Material materialRef(Node n, Map<String, Material> materials) throws SceneException {
        String ref = string(n);
        Material m = materials.get(ref);
        if (m != null) {
            return m;
        }
        if (materials.isEmpty()) {
            throw fail(n, "undefined material " + JsonTree.quote(ref)
                    + "; the scene defines no materials (define it under \"materials\")");
        }
        String close = suggest(ref, materials.keySet());
        throw fail(n, "undefined material " + JsonTree.quote(ref)
                + (close != null ? " (did you mean " + JsonTree.quote(close) + "?)" : "")
                + "; defined materials: " + String.join(", ", materials.keySet().stream()
                        .map(Display::escape).toList()));
    }

    private String name(Node obj, String fallback) throws SceneException {
        if (!obj.has("name")) {
            return fallback;
        }
        String s = string(obj.get("name"));
        if (s.isBlank()) {
            throw fail(obj.get("name"), "name must not be empty (leave it out for the default \""
                    + fallback + "\")");
        }
        // Names are only shown (plan, trace, messages): control characters are kept escaped.
        return Display.escape(s);
    }

    // ---------------------------------------------------------------- lights

    private PointLight light(Node n, int index) throws SceneException {
        typed(n, LIGHT_TYPES, "light");
        String name = name(n, "light #" + index);
        Vec3 position = vec3(n.get("position"));
        Color intensity = color(n.get("intensity"));
        boolean shadows = n.has("shadows") ? bool(n.get("shadows")) : true;
        return new PointLight(position, intensity, shadows, name);
    }

    // ---------------------------------------------------------------- structure checks

    /**
     * Checks that n is an object with a known "type", then its keys; returns the kind.
     *
     * @param family "surface", "material", "camera" or "light", for messages
     */
    private String typed(Node n, Map<String, String> types, String family) throws SceneException {
        object(n);
        if (!n.has("type")) {
            throw fail(n, "missing required key \"type\" (the " + family + " type: one of "
                    + String.join(", ", types.keySet()) + ")");
        }
        Node t = n.get("type");
        String type = string(t);
        String kind = types.get(type);
        if (kind == null) {
            String close = suggest(type, types.keySet());
            throw fail(t, "unknown " + family + " type " + JsonTree.quote(type)
                    + (close != null ? " (did you mean " + JsonTree.quote(close) + "?)" : "")
                    + "; expected one of: " + String.join(", ", types.keySet()));
        }
        checkObject(n, kind);
        return kind;
    }

    /** Unknown keys, then missing required keys, of an object of the given kind. */
    private void checkObject(Node n, String kind) throws SceneException {
        List<String> allowed = ACCEPTED_KEYS.get(kind);
        for (String key : n.fields.keySet()) {
            if (!allowed.contains(key)) {
                String close = suggest(key, allowed);
                StringBuilder m = new StringBuilder("unknown key " + JsonTree.quote(key) + " in "
                        + kindNameOf(kind));
                String elsewhere = siblingWithKey(kind, key);
                if (elsewhere != null) {
                    m.append(" (it belongs to ").append(elsewhere).append(')');
                } else if (close != null) {
                    m.append(" (did you mean ").append(JsonTree.quote(close)).append("?)");
                }
                m.append("; allowed keys: ").append(String.join(", ", allowed));
                throw failKey(n, key, m.toString());
            }
        }
        for (String key : REQUIRED_KEYS.get(kind)) {
            if (!n.has(key)) {
                throw fail(n, "missing required key " + JsonTree.quote(key) + " in "
                        + kindNameOf(kind));
            }
        }
    }

    /** Another kind of the same family (camera, material, surface) that accepts key, or null. */
    private static String siblingWithKey(String kind, String key) {
        for (Map<String, String> family : List.of(CAMERA_TYPES, MATERIAL_TYPES, SURFACE_TYPES)) {
            if (family.containsValue(kind)) {
                for (String other : family.values()) {
                    if (!other.equals(kind) && ACCEPTED_KEYS.get(other).contains(key)) {
                        return kindNameOf(other);
                    }
                }
            }
        }
        return null;
    }

    private Node object(Node n) throws SceneException {
        if (n.kind != Kind.OBJECT) {
            throw fail(n, "expected an object {...}, got " + n.describe());
        }
        return n;
    }

    private Node array(Node n) throws SceneException {
        if (n.kind != Kind.ARRAY) {
            throw fail(n, "expected an array [...], got " + n.describe());
        }
        return n;
    }

    private String string(Node n) throws SceneException {
        if (n.kind != Kind.STRING) {
            throw fail(n, "expected a string, got " + n.describe());
        }
        return n.text;
    }

    private boolean bool(Node n) throws SceneException {
        if (n.kind != Kind.BOOLEAN) {
            throw fail(n, "expected true or false, got " + n.describe());
        }
        return n.bool;
    }

    private double number(Node n) throws SceneException {
        if (n.kind != Kind.NUMBER) {
            throw fail(n, "expected a number, got " + n.describe());
        }
        return n.number;
    }

    private double positive(Node n, String what) throws SceneException {
        double d = number(n);
        if (!(d > 0)) {
            throw fail(n, what + " must be positive, got " + n.text);
        }
        return d;
    }

    private int integer(Node n, int min, int max, String what) throws SceneException {
        double d = number(n);
        if (d != Math.rint(d)) {
            throw fail(n, what + " must be an integer, got " + n.text);
        }
        if (d < min || d > max) {
            throw fail(n, what + " must be from " + min + " to " + max + ", got " + n.text);
        }
        return (int) d;
    }

    private String choice(Node n, List<String> options, String what) throws SceneException {
        String s = string(n);
        if (!options.contains(s)) {
            String close = suggest(s, options);
            throw fail(n, "unknown " + what + " " + JsonTree.quote(s)
                    + (close != null ? " (did you mean " + JsonTree.quote(close) + "?)" : "")
                    + "; expected one of: " + String.join(", ", options));
        }
        return s;
    }

    private Vec3 vec3(Node n) throws SceneException {
        if (n.kind != Kind.ARRAY) {
            throw fail(n, "expected an array of 3 numbers [x, y, z], got " + n.describe());
        }
        if (n.items.size() != 3) {
            throw fail(n, "expected 3 numbers [x, y, z], got " + n.items.size());
        }
        return new Vec3(number(n.items.get(0)), number(n.items.get(1)), number(n.items.get(2)));
    }

    /** [r, g, b] or a single number g meaning [g, g, g]; components finite and non-negative. */
    private Color color(Node n) throws SceneException {
        if (n.kind == Kind.NUMBER) {
            double g = component(n);
            return new Color(g, g, g);
        }
        if (n.kind != Kind.ARRAY) {
            throw fail(n, "expected a colour: [r, g, b] or one number for gray, got " + n.describe());
        }
        if (n.items.size() != 3) {
            throw fail(n, "expected 3 numbers [r, g, b], got " + n.items.size());
        }
        return new Color(component(n.items.get(0)), component(n.items.get(1)),
                component(n.items.get(2)));
    }

    private double component(Node n) throws SceneException {
        double d = number(n);
        if (d < 0) {
            throw fail(n, "colour components must not be negative, got " + n.text);
        }
        return d;
    }

    // ---------------------------------------------------------------- messages

    private SceneException fail(Node n, String message) {
        return new SceneException(file + ":" + n.pos.line() + ":" + n.pos.column() + ": " + n.path
                + ": " + message);
    }

    private SceneException failKey(Node obj, String key, String message) {
        JsonTree.Pos p = obj.keyPos.get(key);
        return new SceneException(file + ":" + p.line() + ":" + p.column() + ": "
                + obj.childPath(key) + ": " + message);
    }

    private static String fmt(Vec3 v) {
        return "[" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + "]";
    }

    private static String fmt(double d) {
        return Display.number(d);
    }

    /**
     * The option closest to what was given, if close enough to be a likely typo (small edit
     * distance, different case, or one containing the other), else null.
     */
    static String suggest(String given, Collection<String> options) {
        String g = given.toLowerCase(Locale.ROOT);
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String o : options) {
            String lo = o.toLowerCase(Locale.ROOT);
            int d = lo.equals(g) ? 0 : editDistance(g, lo);
            if (d < bestDistance) {
                bestDistance = d;
                best = o;
            }
        }
        if (best != null && (bestDistance <= 2 || bestDistance <= g.length() / 3)
                && bestDistance < Math.max(g.length(), best.length())) {
            return best;
        }
        if (g.length() >= 3) {
            for (String o : options) {
                String lo = o.toLowerCase(Locale.ROOT);
                if (lo.contains(g) || g.contains(lo)) {
                    return o;
                }
            }
        }
        return null;
    }

    /** Levenshtein distance. */
    static int editDistance(String a, String b) {
        int[] prev = new int[b.length() + 1];
        int[] cur = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            prev[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            cur[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int sub = prev[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                cur[j] = Math.min(sub, Math.min(prev[j] + 1, cur[j - 1] + 1));
            }
            int[] t = prev;
            prev = cur;
            cur = t;
        }
        return prev[b.length()];
    }

    private static Map<String, String> ordered(String... kv) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            m.put(kv[i], kv[i + 1]);
        }
        return java.util.Collections.unmodifiableMap(m);
    }
}
