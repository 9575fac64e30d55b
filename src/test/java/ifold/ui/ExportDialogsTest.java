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

    /** A number out of the spinner's range, or none, is refused when OK is pressed, not replaced by the last good one. */
    @Test
    void aNumberOutOfRangeIsRefusedNotCutShort() throws Exception {
        JSpinner seconds = ExportDialogs.committing(new JSpinner(new SpinnerNumberModel(120.0, 0.1, 3600, 1)));
        javax.swing.JFormattedTextField text = ((JSpinner.DefaultEditor) seconds.getEditor()).getTextField();
        for (String typed : new String[] {"5", "50", "500", "5000"}) { // as typed, key by key
            javax.swing.SwingUtilities.invokeAndWait(() -> text.setText(typed));
        }
        assertEquals(500.0, ((Number) seconds.getValue()).doubleValue(), "setup: the spinner kept the last number in range");
        String[] problem = new String[1];
        javax.swing.SwingUtilities.invokeAndWait(() -> problem[0] = ExportDialogs.typedProblem(seconds, "seconds"));
        assertEquals("seconds: '5000' is not a number from 0.1 to 3600", problem[0]);
        javax.swing.SwingUtilities.invokeAndWait(() -> text.setText("abc"));
        javax.swing.SwingUtilities.invokeAndWait(() -> problem[0] = ExportDialogs.typedProblem(seconds, "seconds"));
        assertEquals("seconds: 'abc' is not a number from 0.1 to 3600", problem[0]);
        javax.swing.SwingUtilities.invokeAndWait(() -> text.setText("42"));
        javax.swing.SwingUtilities.invokeAndWait(() -> problem[0] = ExportDialogs.typedProblem(seconds, "seconds"));
        assertEquals(null, problem[0]);
        assertEquals(42.0, ((Number) seconds.getValue()).doubleValue());
    }
}
