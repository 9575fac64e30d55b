package ifold.geom;

/**
 * What the core must never be: a class of {@code ifold.geom} that draws with AWT and reaches the
 * renderer, both by names written in full (no import line). Test code, for ArchitectureTest to
 * prove its rules catch it.
 */
final class DrawsOnTheSide {
    private DrawsOnTheSide() {
    }

    static Object corner() {
        return new java.awt.geom.Point2D.Double(ifold.render.FrameExport.captionBand(1280, 720), 0);
    }
}
