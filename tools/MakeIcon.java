import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.GradientPaint;
import java.awt.Graphics2D;
import java.awt.RadialGradientPaint;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.RoundRectangle2D;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Draws the application icon (src/packaging/minigolf.png, 256x256): a green with a hole, a flag and a
 * ball. Run with: java tools/MakeIcon.java src/packaging/minigolf.png
 */
public class MakeIcon {
    public static void main(String[] args) throws Exception {
        int n = 256;
        BufferedImage img = new BufferedImage(n, n, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        // The green: a rounded square, lighter at the top.
        g.setPaint(new GradientPaint(0, 16, new Color(0x7CCB4E), 0, 240, new Color(0x3E8E2A)));
        g.fill(new RoundRectangle2D.Double(12, 12, 232, 232, 56, 56));
        // The hole.
        g.setColor(new Color(0x1B2A12));
        g.fill(new Ellipse2D.Double(118, 150, 64, 22));
        // The flag: pole and pennant.
        g.setColor(new Color(0xF2F2F2));
        g.setStroke(new BasicStroke(6, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.drawLine(150, 160, 150, 40);
        Path2D flag = new Path2D.Double();
        flag.moveTo(153, 40);
        flag.lineTo(214, 60);
        flag.lineTo(153, 82);
        flag.closePath();
        g.setColor(new Color(0xE53935));
        g.fill(flag);
        // The ball, shaded.
        g.setPaint(new RadialGradientPaint(70, 176, 44, new float[]{0f, 1f},
                new Color[]{Color.WHITE, new Color(0xC9CED6)}));
        g.fill(new Ellipse2D.Double(52, 160, 58, 58));
        g.dispose();
        ImageIO.write(img, "png", new File(args[0]));
    }
}
