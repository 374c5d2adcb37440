package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.bot.experiment.RunRecord;
import org.junit.jupiter.api.Test;

class ClassicReportTest {
    static ClassicIndex.Entry entry(String folder, double average, int best) {
        return new ClassicIndex.Entry(folder, "A", List.of("basic"), 100, average, best, 1,
                Path.of("courses", folder, "course.json"), folder);
    }

    @Test
    void figuresCompareWithTheHumanScores() {
        ClassicReport.Import imp = new ClassicReport.Import(List.of(
                entry("A-One", 4.0, 2), entry("A-Two", 8.0, 3)),
                List.of("bad.track: line 4 (T): ..."), List.of());
        List<RunRecord> runs = List.of(
                new RunRecord("A-One", "planner", 1, true, 2, false, 100, 1500),
                new RunRecord("A-Two", "planner", 1, true, 5, false, 100, 2500),
                new RunRecord("A-Two", "planner", 2, false, 30, false, 100, 9000),
                new RunRecord("Other", "planner", 1, true, 1, true, 100, 100), // not in the index: left out
                new RunRecord("A-One", "easy", 1, true, 6, false, 100, 100));
        List<ClassicReport.BotFigures> f = ClassicReport.figures(imp, runs);
        assertEquals(2, f.size());
        ClassicReport.BotFigures p = f.get(0);
        assertEquals("planner", p.bot());
        assertEquals(3, p.runs());
        assertEquals(2, p.tracks());
        assertEquals(2, p.holedWithin());
        assertEquals(1, p.atMostBest());
        assertEquals(3, p.withHumanBest());
        assertEquals(37.0 / 3, p.meanStrokes(), 1e-12);
        assertEquals(20.0 / 3, p.humanMean(), 1e-12);
        assertEquals(9.0, p.slowestSeconds(), 1e-12);
        assertEquals(1.5, f.get(1).ratio(), 1e-12);
        String md = ClassicReport.markdown(imp, f);
        assertTrue(md.startsWith("Import: 2 of 3 tracks imported (2/3 = 66.7%; a file not imported counts as one track), 2 of 2 load\n- not imported: bad.track"), md);
        assertTrue(md.contains("| planner | 2 | 3 | 2/3 = 66.7% | 1/3 = 33.3% | 12.33 | 6.67 | 1.85 | 9 s |"), md);
    }
}
