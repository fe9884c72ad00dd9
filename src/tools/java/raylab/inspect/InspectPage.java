package raylab.inspect;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;

import raylab.render.ImageCompare;

/**
 * The page of {@code raylab inspect}, served on 127.0.0.1 only (no network): the student's render,
 * the reference and the diff heatmap; a click on a pixel asks {@code /pixel?x=X&y=Y}, which traces
 * that pixel now through the student's code and answers both ray trees, the first difference and
 * the drawings. {@code /stamp} names this run, so that a page left open reloads itself when
 * {@code inspect --watch} restarts the command after a save.
 */
public final class InspectPage {
    private static final ObjectMapper JSON = new ObjectMapper();

    private final Inspection inspection;
    private final BufferedImage mine;
    private final Function<Throwable, String> describe;
    private final String stamp = Long.toString(System.nanoTime());
    private final String title;
    private HttpServer server;

    /**
     * @param describe turns an exception thrown by the student's code while tracing into one line
     */
    public InspectPage(Inspection inspection, BufferedImage mine, String title, Function<Throwable, String> describe) {
        this.inspection = inspection;
        this.mine = mine;
        this.title = title;
        this.describe = describe;
    }

    /** Starts serving on 127.0.0.1:port (0: any free port); returns the page's address. */
    public URI start(int port) throws IOException {
        server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 8);
        server.createContext("/", this::handle);
        server.start();
        return URI.create("http://127.0.0.1:" + server.getAddress().getPort() + "/");
    }

    public void stop() {
        if (server != null) {
            server.stop(0);
        }
    }

    private synchronized void handle(HttpExchange ex) throws IOException {
        try (ex) {
            String path = ex.getRequestURI().getPath();
            byte[] body;
            String type;
            int status = 200;
            if (path.equals("/")) {
                body = page().getBytes(StandardCharsets.UTF_8);
                type = "text/html; charset=utf-8";
            } else if (path.equals("/stamp")) {
                body = stamp.getBytes(StandardCharsets.UTF_8);
                type = "text/plain";
            } else if (path.equals("/pixel")) {
                Map<String, String> q = query(ex.getRequestURI().getRawQuery());
                body = pixelJson(q.get("x"), q.get("y")).getBytes(StandardCharsets.UTF_8);
                type = "application/json";
            } else {
                body = "not found".getBytes(StandardCharsets.UTF_8);
                type = "text/plain";
                status = 404;
            }
            ex.getResponseHeaders().set("Content-Type", type);
            ex.getResponseHeaders().set("Cache-Control", "no-store");
            ex.sendResponseHeaders(status, body.length);
            try (OutputStream o = ex.getResponseBody()) {
                o.write(body);
            }
        }
    }

    private static Map<String, String> query(String q) {
        Map<String, String> m = new HashMap<>();
        if (q != null) {
            for (String kv : q.split("&")) {
                int i = kv.indexOf('=');
                if (i > 0) {
                    m.put(kv.substring(0, i), kv.substring(i + 1));
                }
            }
        }
        return m;
    }

    /** The answer to a click: both trees as rows, the first difference, the drawings. */
    String pixelJson(String xs, String ys) throws IOException {
        ObjectNode o = JSON.createObjectNode();
        int x;
        int y;
        try {
            x = Integer.parseInt(xs);
            y = Integer.parseInt(ys);
        } catch (NumberFormatException e) {
            o.put("error", "x and y must be whole numbers");
            return JSON.writeValueAsString(o);
        }
        if (x < 0 || y < 0 || x >= inspection.scene.width || y >= inspection.scene.height) {
            o.put("error", "pixel (" + x + ", " + y + ") is outside the image");
            return JSON.writeValueAsString(o);
        }
        int[] at = inspection.traced(x, y);
        x = at[0];
        y = at[1];
        o.put("x", x);
        o.put("y", y);
        RayTree ref = inspection.reference(x, y);
        RayTree mineTree;
        try {
            mineTree = inspection.mine(x, y);
        } catch (RuntimeException | StackOverflowError e) {
            o.put("error", "your code failed while tracing this pixel: " + describe.apply(e));
            return JSON.writeValueAsString(o);
        }
        Optional<FirstDifference.Difference> d = FirstDifference.of(mineTree, ref, inspection.scene);
        o.put("difference", d.map(FirstDifference.Difference::line).orElse("no difference: your ray tree is the reference's"));
        o.put("differs", d.isPresent());
        o.put("method", d.map(FirstDifference.Difference::method).orElse(""));
        TreeTable.json(TreeTable.rows(mineTree, ref, d), o.putArray("rows"));
        o.put("top", SceneDrawing.svg(inspection.scene, mineTree, ref, true));
        o.put("side", SceneDrawing.svg(inspection.scene, mineTree, ref, false));
        return JSON.writeValueAsString(o);
    }

    static String dataUri(BufferedImage img) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        ImageIO.write(img, "png", b);
        return "data:image/png;base64," + Base64.getEncoder().encodeToString(b.toByteArray());
    }

    /** The page: three pictures, the worst pixel to start with, and the script that asks for a pixel's trees. */
    String page() throws IOException {
        ImageCompare.Result c = ImageCompare.compare(mine, inspection.referenceImage);
        Optional<Inspection.Finding> worst = inspection.worst(mine);
        String start = worst.map(f -> f.x() + "," + f.y()).orElse("");
        StringBuilder b = new StringBuilder();
        b.append("<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>raylab inspect ")
                .append(TreeTable.esc(title)).append("</title><style>")
                .append("body{font-family:sans-serif;margin:12px}figure{display:inline-block;margin:0 12px 8px 0}")
                .append("img.pic{image-rendering:pixelated;cursor:crosshair;border:1px solid #ccc}")
                .append("#difference{font-weight:bold;margin:8px 0;padding:6px;background:#f4f4f4}")
                .append("tr.first{background:#ffd6d6}tr.differs{background:#fff1d6}td,th{padding:2px 6px;text-align:left}")
                .append("</style></head><body><h1 style=\"font-size:20px\">").append(TreeTable.esc(title)).append("</h1>")
                .append("<p id=\"summary\">").append(TreeTable.esc(c.summary()))
                .append(worst.map(f -> "; worst pixel (" + f.x() + ", " + f.y() + ")").orElse(""))
                .append(". Click a pixel of any picture to see your ray tree beside the reference's")
                .append(inspection.reference.stride == 1 ? "" : " (this scene's reference trace keeps every "
                        + inspection.reference.stride + "th pixel of every " + inspection.reference.stride
                        + "th row, to keep the starter small: a click shows the nearest)")
                .append(".</p>");
        for (String[] p : List.of(new String[] {"mine", "your render", dataUri(mine)},
                new String[] {"reference", "reference", dataUri(inspection.referenceImage)},
                new String[] {"diff", "difference", dataUri(c.diff())})) {
            b.append("<figure><img class=\"pic\" id=\"").append(p[0]).append("\" src=\"").append(p[2])
                    .append("\" alt=\"").append(p[1]).append("\"><figcaption>").append(p[1]).append("</figcaption></figure>");
        }
        b.append("<div id=\"pixel\">").append(start.isEmpty() ? "" : "").append("</div>")
                .append("<div id=\"difference\"></div><table id=\"tree\"></table>")
                .append("<div id=\"drawings\" style=\"margin-top:8px\"></div>")
                .append("<script>").append(SCRIPT.replace("@START@", start)).append("</script></body></html>");
        return b.toString();
    }

    private static final String SCRIPT = """
            (function () {
              function esc(s) { return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;'); }
              function show(x, y) {
                document.getElementById('pixel').textContent = 'pixel (' + x + ', ' + y + ')';
                history.replaceState(null, '', '#' + x + ',' + y);
                fetch('/pixel?x=' + x + '&y=' + y).then(function (r) { return r.json(); }).then(function (d) {
                  var diff = document.getElementById('difference');
                  if (d.error) { diff.textContent = d.error; document.getElementById('tree').innerHTML = ''; return; }
                  diff.textContent = d.difference;
                  if (d.x != x || d.y != y) {
                    document.getElementById('pixel').textContent = 'pixel (' + x + ', ' + y + '): the trees of pixel ('
                        + d.x + ', ' + d.y + '), the nearest the reference trace has';
                  }
                  diff.setAttribute('data-method', d.method);
                  var h = '<tr><th>quantity</th><th>yours</th><th>reference</th></tr>';
                  d.rows.forEach(function (r) {
                    h += '<tr class="' + (r.first ? 'first' : r.differs ? 'differs' : 'same') + '"><td>' + esc(r.quantity)
                        + (r.first ? ' <b>(first difference)</b>' : '') + '</td><td>' + esc(r.mine) + '</td><td>'
                        + esc(r.reference) + '</td></tr>';
                  });
                  document.getElementById('tree').innerHTML = h;
                  document.getElementById('drawings').innerHTML = d.top + ' ' + d.side;
                  document.body.setAttribute('data-shown', x + ',' + y);
                });
              }
              ['mine', 'reference', 'diff'].forEach(function (id) {
                var img = document.getElementById(id);
                img.addEventListener('click', function (e) {
                  var r = img.getBoundingClientRect();
                  var x = Math.floor((e.clientX - r.left - img.clientLeft) * img.naturalWidth / img.clientWidth);
                  var y = Math.floor((e.clientY - r.top - img.clientTop) * img.naturalHeight / img.clientHeight);
                  show(Math.max(0, Math.min(img.naturalWidth - 1, x)), Math.max(0, Math.min(img.naturalHeight - 1, y)));
                });
              });
              // A click at image pixel (x, y), as a mouse would make it (the page opened at #X,Y; tests).
              window.raylabClick = function (id, x, y) {
                var img = document.getElementById(id);
                var r = img.getBoundingClientRect();
                // Mouse events have whole-pixel coordinates: the first whole one inside the image pixel.
                var cx = Math.ceil(r.left + img.clientLeft + x * img.clientWidth / img.naturalWidth);
                var cy = Math.ceil(r.top + img.clientTop + y * img.clientHeight / img.naturalHeight);
                img.dispatchEvent(new MouseEvent('click', {clientX: cx, clientY: cy, bubbles: true}));
              };
              window.addEventListener('load', function () {
                var m = /^#(\\d+),(\\d+)$/.exec(location.hash);
                if (m) { window.raylabClick('mine', +m[1], +m[2]); }
                else if ('@START@') { var s = '@START@'.split(','); show(+s[0], +s[1]); }
              });
              var stamp = null;
              setInterval(function () {
                fetch('/stamp').then(function (r) { return r.text(); }).then(function (s) {
                  if (stamp !== null && s !== stamp) { location.reload(); }
                  stamp = s;
                }).catch(function () {});
              }, 1500);
            })();
            """;
}
