package raylab.study;

import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Path;
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
        new Color(204, 121, 167), new Color(230, 159, 0), new Color(86, 180, 233), new Color(0, 0, 0)};

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

    /** Writes the chart as DIR/file (a .png name), atomically. */
    static void save(Chart<?, ?> chart, Path dir, String file) throws IOException {
        PngFiles.write(BitmapEncoder.getBufferedImage(chart), dir.resolve(file));
    }
}
