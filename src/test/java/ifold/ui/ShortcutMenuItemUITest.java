package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import javax.swing.KeyStroke;
import org.junit.jupiter.api.Test;

class ShortcutMenuItemUITest {
    @Test
    void punctuationKeysAreWrittenAsTheirSigns() {
        KeyStroke previous = KeyStroke.getKeyStroke(KeyEvent.VK_OPEN_BRACKET, InputEvent.CTRL_DOWN_MASK);
        String written = "Ctrl+" + KeyEvent.getKeyText(KeyEvent.VK_OPEN_BRACKET);
        assertEquals("Ctrl+Open Bracket", written, "the JDK's words, as the menus showed them");
        assertEquals("Ctrl+[", ShortcutMenuItemUI.text(previous, written));
        assertEquals("Ctrl+]", ShortcutMenuItemUI.text(KeyStroke.getKeyStroke(KeyEvent.VK_CLOSE_BRACKET, InputEvent.CTRL_DOWN_MASK),
                "Ctrl+" + KeyEvent.getKeyText(KeyEvent.VK_CLOSE_BRACKET)));
        // Letters and function keys keep their names.
        assertEquals("Ctrl+O", ShortcutMenuItemUI.text(KeyStroke.getKeyStroke(KeyEvent.VK_O, InputEvent.CTRL_DOWN_MASK), "Ctrl+O"));
        assertEquals("F1", ShortcutMenuItemUI.text(KeyStroke.getKeyStroke(KeyEvent.VK_F1, 0), "F1"));
    }
}
