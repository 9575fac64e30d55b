package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;
import org.junit.jupiter.api.Test;

/** The export dialog's numbers are what is typed, whether or not the field was left before OK. */
class ExportDialogsTest {
    @Test
    void aSpinnersValueFollowsTheNumberTypedBeforeTheFieldIsLeft() throws Exception {
        JSpinner seconds = ExportDialogs.committing(new JSpinner(new SpinnerNumberModel(120.0, 0.1, 3600, 1)));
        javax.swing.JFormattedTextField text = ((JSpinner.DefaultEditor) seconds.getEditor()).getTextField();
        javax.swing.SwingUtilities.invokeAndWait(() -> text.setText("42"));
        assertEquals(42.0, ((Number) seconds.getValue()).doubleValue(), "typed, not left: the movie's seconds");
        JSpinner plain = new JSpinner(new SpinnerNumberModel(120.0, 0.1, 3600, 1));
        javax.swing.JFormattedTextField plainText = ((JSpinner.DefaultEditor) plain.getEditor()).getTextField();
        javax.swing.SwingUtilities.invokeAndWait(() -> plainText.setText("42"));
        assertEquals(120.0, ((Number) plain.getValue()).doubleValue(), "setup: a spinner left as Swing makes it waits for the focus to go");
    }
}
