package minigolf.bot.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The run plan's fixed order and how shards divide it. */
class ShardTest {
    private static final RunPlan PLAN = new RunPlan(List.of("a", "b", "c"), List.of("planner", "newton"), 5);

    @Test
    void runsGoCourseByCourseBotByBotSeedBySeed() {
        assertEquals(30, PLAN.size());
        assertEquals(new RunPlan.Run(0, "a", "planner", 1), PLAN.run(0));
        assertEquals(new RunPlan.Run(4, "a", "planner", 5), PLAN.run(4));
        assertEquals(new RunPlan.Run(5, "a", "newton", 1), PLAN.run(5));
        assertEquals(new RunPlan.Run(10, "b", "planner", 1), PLAN.run(10));
        assertEquals(new RunPlan.Run(29, "c", "newton", 5), PLAN.run(29));
        Set<String> keys = new HashSet<>();
        for (int i = 0; i < PLAN.size(); i++) {
            RunPlan.Run r = PLAN.run(i);
            assertTrue(keys.add(r.course() + "/" + r.bot() + "/" + r.seed()), "run " + i + " repeats a key");
        }
        assertThrows(IndexOutOfBoundsException.class, () -> PLAN.run(30));
    }

    @Test
    void theShardsOfAPlanHoldEveryRunExactlyOnce() {
        for (int n : new int[] {1, 2, 3, 4, 7, 30, 31, 100}) {
            int[] owners = new int[PLAN.size()];
            int sizes = 0;
            for (int k = 0; k < n; k++) {
                Shard s = new Shard(k, n);
                int count = 0;
                for (int i = 0; i < PLAN.size(); i++) {
                    if (s.contains(i)) {
                        owners[i]++;
                        count++;
                    }
                }
                assertEquals(count, s.size(PLAN.size()), "size of shard " + s);
                sizes += count;
            }
            assertEquals(PLAN.size(), sizes);
            for (int i = 0; i < PLAN.size(); i++) assertEquals(1, owners[i], "run " + i + " with " + n + " shards");
        }
        // Every N-th run: shard 1/4 of 30 runs is 1, 5, 9, ..., 29.
        assertEquals(8, new Shard(1, 4).size(30));
        assertEquals(7, new Shard(3, 4).size(30));
    }

    @Test
    void parsesKSlashN() {
        assertEquals(new Shard(2, 4), Shard.parse("2/4"));
        assertEquals(new Shard(0, 1), Shard.parse(" 0/1 "));
        assertEquals("shard-2-of-4", Shard.parse("2/4").folderName());
        assertEquals("--shard: K must be 0..3 (K counts from 0), got '4/4'",
                assertThrows(ExperimentException.class, () -> Shard.parse("4/4")).getMessage());
        assertEquals("--shard: expected K/N (e.g. 0/4), got '3'",
                assertThrows(ExperimentException.class, () -> Shard.parse("3")).getMessage());
        assertEquals("--shard: K in 'x/4': not a whole number: 'x'",
                assertThrows(ExperimentException.class, () -> Shard.parse("x/4")).getMessage());
        assertEquals("--shard: N must be at least 1, got '0/0'",
                assertThrows(ExperimentException.class, () -> Shard.parse("0/0")).getMessage());
    }

    @Test
    void slurmArrayTasksBecomeShards() {
        assertNull(Shard.fromEnvironment(Map.of(), null));
        assertEquals(new Shard(3, 4), Shard.fromEnvironment(Map.of("SLURM_ARRAY_TASK_ID", "3",
                "SLURM_ARRAY_TASK_COUNT", "4", "SLURM_ARRAY_TASK_MIN", "0", "SLURM_ARRAY_TASK_STEP", "1"), null));
        // --array=1-4 counts from 1; --array=0-30:10 steps by 10.
        assertEquals(new Shard(0, 4), Shard.fromEnvironment(Map.of("SLURM_ARRAY_TASK_ID", "1",
                "SLURM_ARRAY_TASK_COUNT", "4", "SLURM_ARRAY_TASK_MIN", "1"), null));
        assertEquals(new Shard(2, 4), Shard.fromEnvironment(Map.of("SLURM_ARRAY_TASK_ID", "20",
                "SLURM_ARRAY_TASK_COUNT", "4", "SLURM_ARRAY_TASK_MIN", "0", "SLURM_ARRAY_TASK_STEP", "10"), 4));
        // --array=0,5,7 is not an even spacing: refused rather than guessed.
        ExperimentException uneven = assertThrows(ExperimentException.class, () -> Shard.fromEnvironment(Map.of(
                "SLURM_ARRAY_TASK_ID", "7", "SLURM_ARRAY_TASK_COUNT", "3", "SLURM_ARRAY_TASK_MIN", "0"), null));
        assertTrue(uneven.getMessage().startsWith("SLURM_ARRAY_TASK_ID 7 is not one of 3 evenly spaced tasks"), uneven.getMessage());
        assertEquals("--shards 5 disagrees with the Slurm array's 4 tasks (SLURM_ARRAY_TASK_COUNT)",
                assertThrows(ExperimentException.class, () -> Shard.fromEnvironment(Map.of("SLURM_ARRAY_TASK_ID", "0",
                        "SLURM_ARRAY_TASK_COUNT", "4"), 5)).getMessage());
    }

    @Test
    void kubernetesIndexedJobsNeedTheShardCount() {
        assertEquals(new Shard(5, 8), Shard.fromEnvironment(Map.of("JOB_COMPLETION_INDEX", "5"), 8));
        assertTrue(assertThrows(ExperimentException.class, () -> Shard.fromEnvironment(Map.of("JOB_COMPLETION_INDEX", "5"), null))
                .getMessage().startsWith("JOB_COMPLETION_INDEX is set (a Kubernetes Indexed Job) but the number of shards is not"));
        assertEquals("JOB_COMPLETION_INDEX 8 is outside 0..7 (--shards 8)", assertThrows(ExperimentException.class,
                () -> Shard.fromEnvironment(Map.of("JOB_COMPLETION_INDEX", "8"), 8)).getMessage());
        assertTrue(assertThrows(ExperimentException.class, () -> Shard.fromEnvironment(Map.of(), 4))
                .getMessage().startsWith("--shards 4 needs a shard index from the scheduler"));
    }
}
