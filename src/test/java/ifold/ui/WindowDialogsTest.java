package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The window's save dialogs ask before they replace a file that is there (File, Export OBJ on cube.off offered cube.obj, another model). */
class WindowDialogsTest {
    @TempDir
    Path dir;

    @Test
    void aSaveDialogAsksBeforeItReplacesAFileThatIsThere() throws Exception {
        Path there = Files.writeString(dir.resolve("cube.obj"), "v 0 0 0\n");
        List<Path> asked = new ArrayList<>();
        List<String> approved = new ArrayList<>();
        boolean[] answer = {false};
        WindowDialogs.SaveChooser chooser = new WindowDialogs.SaveChooser(dir.toString(), file -> {
            asked.add(file);
            return answer[0];
        });
        chooser.addActionListener(event -> approved.add(event.getActionCommand()));
        SwingUtilities.invokeAndWait(() -> {
            chooser.setSelectedFile(there.toFile());
            chooser.approveSelection(); // answered no: the dialog stays
        });
        assertEquals(List.of(there), asked, "asked about the file that is there");
        assertEquals(List.of(), approved, "not replaced without a yes");
        answer[0] = true;
        SwingUtilities.invokeAndWait(chooser::approveSelection);
        assertEquals(List.of(JFileChooser.APPROVE_SELECTION), approved, "replaced on a yes");
        SwingUtilities.invokeAndWait(() -> {
            chooser.setSelectedFile(dir.resolve("new.obj").toFile());
            chooser.approveSelection();
        });
        assertEquals(2, asked.size(), "a new file is not asked about");
        assertEquals(2, approved.size(), "and is approved at once");
        answer[0] = false;
        SwingUtilities.invokeAndWait(() -> {
            chooser.setFileFilter(new javax.swing.filechooser.FileNameExtensionFilter("OBJ", "obj"));
            chooser.setSelectedFile(dir.resolve("cube").toFile()); // typed without its extension
            chooser.approveSelection();
        });
        assertEquals(there, asked.get(asked.size() - 1), "the file the export would replace, with its extension");
        assertEquals(2, approved.size());
    }
}
