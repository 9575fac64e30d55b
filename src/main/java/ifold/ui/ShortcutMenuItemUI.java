package ifold.ui;

import com.formdev.flatlaf.ui.FlatMenuItemRenderer;
import com.formdev.flatlaf.ui.FlatMenuItemUI;
import java.awt.event.KeyEvent;
import java.util.Map;
import javax.swing.JComponent;
import javax.swing.KeyStroke;
import javax.swing.plaf.ComponentUI;

/**
 * FlatLaf's menu item, with shortcuts of punctuation keys written as the key's sign: the JDK
 * names {@code VK_OPEN_BRACKET} "Open Bracket", so Fold > Previous fold read "Ctrl+Open
 * Bracket" where the key shows "[".
 */
public class ShortcutMenuItemUI extends FlatMenuItemUI {
    private static final Map<Integer, String> SIGNS = Map.of(KeyEvent.VK_OPEN_BRACKET, "[", KeyEvent.VK_CLOSE_BRACKET, "]",
            KeyEvent.VK_COMMA, ",", KeyEvent.VK_PERIOD, ".", KeyEvent.VK_SLASH, "/", KeyEvent.VK_SEMICOLON, ";",
            KeyEvent.VK_MINUS, "-", KeyEvent.VK_EQUALS, "=", KeyEvent.VK_BACK_SLASH, "\\");

    /** Swing's factory, named by the look's {@code MenuItemUI} key. */
    public static ComponentUI createUI(JComponent item) {
        return new ShortcutMenuItemUI();
    }

    /** How the menus write {@code stroke}: the JDK's words, but a sign for a punctuation key. */
    static String text(KeyStroke stroke, String written) {
        String sign = SIGNS.get(stroke.getKeyCode());
        String name = KeyEvent.getKeyText(stroke.getKeyCode());
        return sign == null || !written.endsWith(name) ? written : written.substring(0, written.length() - name.length()) + sign;
    }

    @Override
    protected FlatMenuItemRenderer createRenderer() {
        return new FlatMenuItemRenderer(menuItem, checkIcon, arrowIcon, acceleratorFont, acceleratorDelimiter) {
            @Override
            protected String getTextForAccelerator(KeyStroke accelerator) {
                return text(accelerator, super.getTextForAccelerator(accelerator));
            }
        };
    }
}
