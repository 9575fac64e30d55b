package ifold.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.geom.Path2D;
import java.util.Locale;
import javax.swing.JComponent;
import javax.swing.JTextField;

/**
 * The zig-zag's triangle drawn in the plane, its corners A, B, C dragged with the mouse: a
 * drag writes the corners into the text field (which stays the one source of the values, so
 * that what is typed and what is dragged are checked alike). A triangle in space (nine
 * numbers) is drawn from above and not dragged.
 */
final class TriangleSketch extends JComponent {
    private static final long serialVersionUID = 1L;
    private static final int MARGIN = 18;
    private static final int GRAB = 10;

    private final JTextField corners;
    /** The corner being dragged, or -1. */
    private int dragged = -1;
    /** The view's scale and origin, fixed while dragging so that the sketch does not swim under the mouse. */
    private double scale;
    private double originX;
    private double originY;

    TriangleSketch(JTextField corners) {
        this.corners = corners;
        setPreferredSize(new Dimension(220, 150));
        setToolTipText("drag a corner to move it");
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                double[] xy = values();
                dragged = -1;
                if (xy == null || xy.length != 6) {
                    return;
                }
                for (int i = 0; i < 3; i++) {
                    if (Math.hypot(screenX(xy[2 * i]) - e.getX(), screenY(xy[2 * i + 1]) - e.getY()) <= GRAB) {
                        dragged = i;
                    }
                }
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                double[] xy = values();
                if (dragged < 0 || xy == null || xy.length != 6) {
                    return;
                }
                xy[2 * dragged] = round((e.getX() - originX) / scale);
                xy[2 * dragged + 1] = round((originY - e.getY()) / scale);
                StringBuilder text = new StringBuilder();
                for (int i = 0; i < 6; i++) {
                    text.append(i == 0 ? "" : ",").append(format(xy[i]));
                }
                corners.setText(text.toString());
                repaint();
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                dragged = -1;
                repaint(); // refit the view to where the corners now are
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
    }

    /** Where corner {@code i} is drawn, in the sketch's pixels (null if the field holds no triangle): for tests. */
    java.awt.Point corner(int i) {
        double[] xy = values();
        if (xy == null) {
            return null;
        }
        fit(xy);
        return new java.awt.Point((int) Math.round(screenX(xy[2 * i])), (int) Math.round(screenY(xy[2 * i + 1])));
    }

    /** Dragged corners land on a tenth of a unit: values that read well, typed or not. */
    private static double round(double value) {
        return Math.round(value * 10) / 10.0;
    }

    private static String format(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : String.format(Locale.ROOT, "%s", value);
    }

    /** The numbers in the field, or null if they are not six or nine numbers. */
    private double[] values() {
        String[] parts = corners.getText().split(",", -1);
        if (parts.length != 6 && parts.length != 9) {
            return null;
        }
        double[] values = new double[parts.length];
        try {
            for (int i = 0; i < parts.length; i++) {
                values[i] = Double.parseDouble(parts[i].strip());
                if (!Double.isFinite(values[i])) {
                    return null;
                }
            }
        } catch (NumberFormatException e) {
            return null;
        }
        if (values.length == 9) {
            return new double[] {values[0], values[1], values[3], values[4], values[6], values[7]}; // from above
        }
        return values;
    }

    private double screenX(double x) {
        return originX + x * scale;
    }

    private double screenY(double y) {
        return originY - y * scale;
    }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g2.setColor(new Color(0xF4F6F8));
            g2.fillRoundRect(0, 0, getWidth() - 1, getHeight() - 1, 8, 8);
            double[] xy = values();
            if (xy == null) {
                g2.setColor(Color.GRAY);
                g2.drawString("not six numbers", MARGIN, getHeight() / 2);
                return;
            }
            if (dragged < 0) {
                fit(xy);
            }
            Path2D.Double outline = new Path2D.Double();
            outline.moveTo(screenX(xy[0]), screenY(xy[1]));
            outline.lineTo(screenX(xy[2]), screenY(xy[3]));
            outline.lineTo(screenX(xy[4]), screenY(xy[5]));
            outline.closePath();
            g2.setColor(new Color(0x7D8A99));
            g2.fill(outline);
            g2.setColor(new Color(0x1E8C3A));
            g2.setStroke(new BasicStroke(2f));
            g2.draw(outline);
            for (int i = 0; i < 3; i++) {
                int x = (int) Math.round(screenX(xy[2 * i]));
                int y = (int) Math.round(screenY(xy[2 * i + 1]));
                g2.setColor(i == dragged ? new Color(0xE07020) : new Color(0x1E4C8C));
                g2.fillOval(x - 5, y - 5, 10, 10);
                g2.setColor(Color.DARK_GRAY);
                g2.drawString(ParameterPanel.CORNERS[i], x + 7, y - 5);
            }
        } finally {
            g2.dispose();
        }
    }

    /** Scales the triangle into the sketch with a margin, the same scale both ways. */
    private void fit(double[] xy) {
        double minX = Math.min(xy[0], Math.min(xy[2], xy[4]));
        double maxX = Math.max(xy[0], Math.max(xy[2], xy[4]));
        double minY = Math.min(xy[1], Math.min(xy[3], xy[5]));
        double maxY = Math.max(xy[1], Math.max(xy[3], xy[5]));
        double spanX = Math.max(maxX - minX, 1e-12);
        double spanY = Math.max(maxY - minY, 1e-12);
        scale = Math.min((getWidth() - 2.0 * MARGIN) / spanX, (getHeight() - 2.0 * MARGIN) / spanY);
        originX = (getWidth() - spanX * scale) / 2 - minX * scale;
        originY = (getHeight() + spanY * scale) / 2 + minY * scale;
    }
}
