package raylab.study;

import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

import raylab.render.PngFiles;

/** XChart plots in one style, written as PNG files atomically. */
final class Plots {
    static final int WIDTH = 760;
    static final int HEIGHT = 460;
    /** A palette that stays readable in print and for colour-blind readers (Okabe–Ito). */
    static final Color[] PALETTE = {new Color(0, 114, 178), new Color(213, 94, 0), new Color(0, 158, 115),
        new Color(204, 121, 167), new Color(230, 159, 0), new Color(86, 180, 233), new Color(120, 70, 20)};

    private Plots() {
    }

    static XYChart xy(String title, String xTitle, String yTitle, boolean logX, boolean logY) {
        return xy(WIDTH, title, xTitle, yTitle, logX, logY);
    }

    static XYChart xy(int width, String title, String xTitle, String yTitle, boolean logX, boolean logY) {
        XYChart chart = new XYChartBuilder().width(width).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        Styler s = chart.getStyler();
        style(s);
        chart.getStyler().setXAxisLogarithmic(logX);
        chart.getStyler().setYAxisLogarithmic(logY);
        chart.getStyler().setDefaultSeriesRenderStyle(org.knowm.xchart.XYSeries.XYSeriesRenderStyle.Line);
        return chart;
    }

    /** Puts the legend in one column to the right of the plot, for charts with many series. */
    static void legendRight(org.knowm.xchart.internal.chartpart.Chart<?, ?> chart) {
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setLegendLayout(Styler.LegendLayout.Vertical);
    }

    static CategoryChart bars(String title, String xTitle, String yTitle) {
        CategoryChart chart = new CategoryChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setLabelsVisible(false);
        chart.getStyler().setYAxisDecimalPattern("#,##0.###");
        return chart;
    }

    private static void style(Styler s) {
        s.setChartBackgroundColor(Color.WHITE);
        s.setPlotBackgroundColor(Color.WHITE);
        s.setLegendPosition(Styler.LegendPosition.OutsideS);
        s.setLegendLayout(Styler.LegendLayout.Horizontal);
        s.setSeriesColors(PALETTE);
        s.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        s.setAntiAlias(true);
    }

    /** A line with markers. */
    static XYSeries line(XYChart chart, String name, double[] x, double[] y, int colour) {
        XYSeries s = chart.addSeries(name, x, y);
        s.setLineColor(PALETTE[colour % PALETTE.length]);
        s.setMarkerColor(PALETTE[colour % PALETTE.length]);
        s.setMarker(SeriesMarkers.CIRCLE);
        return s;
    }

    /**
     * A timed series: the medians as a line with markers, and the spread of the runs as an error
     * bar from the minimum to the maximum at each point (a two-point series left out of the
     * legend).
     */
    static void timed(XYChart chart, String name, double[] x, Timing.Stats[] stats, int colour) {
        double[] med = new double[x.length];
        double[] lo = new double[x.length];
        double[] hi = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            med[i] = stats[i].median();
            lo[i] = stats[i].min();
            hi[i] = stats[i].max();
        }
        line(chart, name, x, med, colour);
        Color c = PALETTE[colour % PALETTE.length];
        for (int i = 0; i < x.length; i++) {
            if (hi[i] > lo[i]) {
                XYSeries bar = chart.addSeries(name + " spread " + i, new double[] {x[i], x[i]},
                        new double[] {lo[i], hi[i]});
                bar.setLineColor(c);
                bar.setMarkerColor(c);
                bar.setMarker(SeriesMarkers.DIAMOND);
                bar.setShowInLegend(false);
            }
        }
    }

    /** A dashed guide line (for example a slope of −1/2 on log-log axes). */
    static void guide(XYChart chart, String name, double[] x, double[] y) {
        XYSeries s = chart.addSeries(name, x, y);
        s.setLineColor(Color.GRAY);
        s.setLineStyle(new java.awt.BasicStroke(1.2f, java.awt.BasicStroke.CAP_BUTT,
                java.awt.BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f));
        s.setMarker(SeriesMarkers.NONE);
    }

    static void bars(CategoryChart chart, String name, List<String> x, List<? extends Number> y) {
        chart.addSeries(name, x, y);
    }

    /** One point of a front: a method (at one setting) with its measured cost and its error. */
    record FrontPoint(Timing.Stats cost, double error) {
    }

    /** One method on a front: a single point, or a curve over a setting (samples per pixel, triangles). */
    record Curve(String name, List<FrontPoint> points, boolean joined) {
        /** A curve whose points are joined in order (a setting that grows). */
        Curve(String name, List<FrontPoint> points) {
            this(name, points, true);
        }
    }

    /**
     * Indices (curve, point) of the non-dominated points: no other point has a cost and an
     * error both at most as large, one of them smaller. Costs compare by median.
     */
    static boolean[][] nonDominated(List<Curve> curves) {
        boolean[][] front = new boolean[curves.size()][];
        for (int c = 0; c < curves.size(); c++) {
            List<FrontPoint> ps = curves.get(c).points();
            front[c] = new boolean[ps.size()];
            for (int i = 0; i < ps.size(); i++) {
                FrontPoint p = ps.get(i);
                boolean dominated = false;
                for (Curve other : curves) {
                    for (FrontPoint q : other.points()) {
                        double qc = q.cost().median();
                        double pc = p.cost().median();
                        if (qc <= pc && q.error() <= p.error() && (qc < pc || q.error() < p.error())) {
                            dominated = true;
                        }
                    }
                }
                front[c][i] = !dominated;
            }
        }
        return front;
    }

    /**
     * An error-against-cost plot: each method a point or a curve at the median cost, with a
     * horizontal bar over the middle half of its runs (first to third quartile), and the front (the
     * non-dominated points: nothing else is both cheaper and more accurate) joined by a black
     * dashed line; the legend marks the methods on it. On a logarithmic error axis an error of 0
     * is drawn at {@code floor} (the caption says so).
     */
    static XYChart front(String title, String xTitle, String yTitle, boolean logX, boolean logY, double floor,
            List<Curve> curves) {
        XYChart chart = xy(WIDTH, title, xTitle, yTitle, logX, logY);
        legendRight(chart);
        boolean[][] front = nonDominated(curves);
        List<double[]> fp = new ArrayList<>();
        for (int c = 0; c < curves.size(); c++) {
            Curve curve = curves.get(c);
            int n = curve.points().size();
            double[] x = new double[n];
            double[] y = new double[n];
            boolean onFront = false;
            for (int i = 0; i < n; i++) {
                FrontPoint p = curve.points().get(i);
                x[i] = p.cost().median();
                y[i] = logY ? Math.max(p.error(), floor) : p.error();
                if (front[c][i]) {
                    fp.add(new double[] {x[i], y[i]});
                    onFront = true;
                }
            }
            XYSeries s = line(chart, curve.name() + (onFront ? " (on the front)" : ""), x, y, c);
            if (n == 1 || !curve.joined()) {
                s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            }
            Color colour = PALETTE[c % PALETTE.length];
            for (int i = 0; i < n; i++) {
                Timing.Stats cost = curve.points().get(i).cost();
                if (cost.q3() > cost.q1()) {
                    XYSeries bar = chart.addSeries(curve.name() + " spread " + i, new double[] {cost.q1(), cost.q3()},
                            new double[] {y[i], y[i]});
                    bar.setLineColor(colour);
                    bar.setMarker(SeriesMarkers.NONE);
                    bar.setShowInLegend(false);
                }
            }
        }
        fp.sort((a, b) -> Double.compare(a[0], b[0]));
        if (fp.size() >= 2) {
            XYSeries f = chart.addSeries("the front (non-dominated)", fp.stream().mapToDouble(p -> p[0]).toArray(),
                    fp.stream().mapToDouble(p -> p[1]).toArray());
            f.setLineColor(Color.BLACK);
            f.setLineStyle(new java.awt.BasicStroke(1.5f, java.awt.BasicStroke.CAP_BUTT,
                    java.awt.BasicStroke.JOIN_MITER, 10f, new float[] {5f, 4f}, 0f));
            f.setMarker(SeriesMarkers.NONE);
        }
        chart.getStyler().setMarkerSize(9);
        return chart;
    }

    /** The names of the curves with at least one non-dominated point. */
    static List<String> frontNames(List<Curve> curves) {
        boolean[][] front = nonDominated(curves);
        List<String> out = new ArrayList<>();
        for (int c = 0; c < curves.size(); c++) {
            for (boolean b : front[c]) {
                if (b) {
                    out.add(curves.get(c).name());
                    break;
                }
            }
        }
        return out;
    }

    /** Writes the chart as DIR/file (a .png name), atomically. */
    static void save(Chart<?, ?> chart, Path dir, String file) throws IOException {
        PngFiles.write(BitmapEncoder.getBufferedImage(chart), dir.resolve(file));
    }
}
