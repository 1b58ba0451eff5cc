package org.tinysep.benchmarks;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;

/** PNG bar charts drawn with java.awt (headless): one group of bars per label, one colour per series. */
final class Plot {

    record Series(String name, List<Double> values) {
    }

    private static final Color[] COLOURS = {new Color(0x3b6ea5), new Color(0xd08c2b), new Color(0x6a9a3a),
        new Color(0x9a3a6a)};

    private Plot() {
    }

    static void bars(Path file, String title, String unit, List<String> labels, List<Series> series) throws IOException {
        System.setProperty("java.awt.headless", "true");
        int w = 900;
        int h = 420;
        int left = 80;
        int bottom = 70;
        int top = 50;
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, h);
        double max = series.stream().flatMap(s -> s.values().stream()).filter(v -> !v.isNaN())
                .mapToDouble(Double::doubleValue).max().orElse(1);
        max = max <= 0 ? 1 : max * 1.1;
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 16));
        g.drawString(title, left, 28);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        int plotH = h - top - bottom;
        int plotW = w - left - 20;
        g.setStroke(new BasicStroke(1));
        for (int i = 0; i <= 4; i++) {
            int y = top + plotH - plotH * i / 4;
            g.setColor(new Color(0xdddddd));
            g.drawLine(left, y, left + plotW, y);
            g.setColor(Color.DARK_GRAY);
            g.drawString(String.format(Locale.ROOT, "%.3g", max * i / 4), 8, y + 4);
        }
        g.drawString(unit, 8, top - 10);
        int groups = Math.max(1, labels.size());
        int groupW = plotW / groups;
        int barW = Math.max(4, (groupW - 20) / Math.max(1, series.size()));
        for (int gi = 0; gi < labels.size(); gi++) {
            int x0 = left + gi * groupW + 10;
            for (int si = 0; si < series.size(); si++) {
                Double v = gi < series.get(si).values().size() ? series.get(si).values().get(gi) : Double.NaN;
                if (v == null || v.isNaN()) {
                    continue;
                }
                int bh = (int) (plotH * v / max);
                g.setColor(COLOURS[si % COLOURS.length]);
                g.fillRect(x0 + si * barW, top + plotH - bh, barW - 2, bh);
            }
            g.setColor(Color.BLACK);
            g.drawString(labels.get(gi), x0, top + plotH + 16);
        }
        for (int si = 0; si < series.size(); si++) {
            g.setColor(COLOURS[si % COLOURS.length]);
            g.fillRect(left + si * 200, h - 28, 12, 12);
            g.setColor(Color.BLACK);
            g.drawString(series.get(si).name(), left + si * 200 + 18, h - 18);
        }
        g.dispose();
        Files.createDirectories(file.getParent());
        ImageIO.write(img, "png", file.toFile());
    }
}
