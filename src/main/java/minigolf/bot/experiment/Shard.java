package minigolf.bot.experiment;

import java.util.Map;

/**
 * Shard K of N (K from 0): the runs whose index leaves remainder K when divided by N. Taking every
 * N-th run, rather than a block, gives each shard a share of every course and bot, so shards of
 * one experiment take about the same time.
 */
public record Shard(int index, int count) {
    public Shard {
        if (count < 1) throw new ExperimentException("shard count must be at least 1, got " + count);
        if (index < 0 || index >= count) {
            throw new ExperimentException("shard " + index + "/" + count + ": the index must be 0.." + (count - 1));
        }
    }

    /** Parses "K/N" as written on the command line. */
    public static Shard parse(String text) {
        String[] parts = text.trim().split("/", -1);
        if (parts.length != 2) throw new ExperimentException("--shard: expected K/N (e.g. 0/4), got '" + text + "'");
        int k = parseInt(parts[0], "--shard: K in '" + text + "'");
        int n = parseInt(parts[1], "--shard: N in '" + text + "'");
        if (n < 1) throw new ExperimentException("--shard: N must be at least 1, got '" + text + "'");
        if (k < 0 || k >= n) throw new ExperimentException("--shard: K must be 0.." + (n - 1) + " (K counts from 0), got '" + text + "'");
        return new Shard(k, n);
    }

    /**
     * The shard a scheduler assigned through the environment, or null when none did: a Slurm array
     * task (SLURM_ARRAY_TASK_ID, _MIN, _STEP, _COUNT), or a Kubernetes Indexed Job's
     * JOB_COMPLETION_INDEX with the shard count given as {@code shards} (Kubernetes does not pass
     * the Job's completions to the pod).
     *
     * @param shards the --shards option, or null
     */
    public static Shard fromEnvironment(Map<String, String> env, Integer shards) {
        String slurmId = env.get("SLURM_ARRAY_TASK_ID");
        if (slurmId != null && !slurmId.isBlank()) {
            int id = parseInt(slurmId, "SLURM_ARRAY_TASK_ID");
            int count = parseInt(required(env, "SLURM_ARRAY_TASK_COUNT"), "SLURM_ARRAY_TASK_COUNT");
            int min = env.containsKey("SLURM_ARRAY_TASK_MIN") ? parseInt(env.get("SLURM_ARRAY_TASK_MIN"), "SLURM_ARRAY_TASK_MIN") : 0;
            int step = env.containsKey("SLURM_ARRAY_TASK_STEP") ? parseInt(env.get("SLURM_ARRAY_TASK_STEP"), "SLURM_ARRAY_TASK_STEP") : 1;
            if (step < 1 || (id - min) % step != 0 || (id - min) / step >= count || id < min) {
                throw new ExperimentException("SLURM_ARRAY_TASK_ID " + id + " is not one of " + count
                        + " evenly spaced tasks from " + min + " (step " + step
                        + "): submit the array as --array=0-" + (count - 1) + ", or give --shard K/N");
            }
            if (shards != null && shards != count) {
                throw new ExperimentException("--shards " + shards + " disagrees with the Slurm array's "
                        + count + " tasks (SLURM_ARRAY_TASK_COUNT)");
            }
            return new Shard((id - min) / step, count);
        }
        String k8sIndex = env.get("JOB_COMPLETION_INDEX");
        if (k8sIndex != null && !k8sIndex.isBlank()) {
            if (shards == null) {
                throw new ExperimentException("JOB_COMPLETION_INDEX is set (a Kubernetes Indexed Job) but the number of "
                        + "shards is not: add --shards N with N the Job's completions, or give --shard K/N");
            }
            int index = parseInt(k8sIndex, "JOB_COMPLETION_INDEX");
            if (index < 0 || index >= shards) {
                throw new ExperimentException("JOB_COMPLETION_INDEX " + index + " is outside 0.." + (shards - 1)
                        + " (--shards " + shards + ")");
            }
            return new Shard(index, shards);
        }
        if (shards != null) {
            throw new ExperimentException("--shards " + shards + " needs a shard index from the scheduler "
                    + "(JOB_COMPLETION_INDEX or SLURM_ARRAY_TASK_ID), and neither is set; give --shard K/N instead");
        }
        return null;
    }

    public boolean contains(int run) {
        return run % count == index;
    }

    /** Runs of a plan with {@code total} runs that fall in this shard. */
    public int size(int total) {
        return total / count + (index < total % count ? 1 : 0);
    }

    /** The shard's own folder under the experiment's --out folder. */
    public String folderName() {
        return "shard-" + index + "-of-" + count;
    }

    @Override
    public String toString() {
        return index + "/" + count;
    }

    private static String required(Map<String, String> env, String name) {
        String value = env.get(name);
        if (value == null || value.isBlank()) {
            throw new ExperimentException("SLURM_ARRAY_TASK_ID is set but " + name + " is not (Slurm older than 18.08?); give --shard K/N");
        }
        return value;
    }

    private static int parseInt(String text, String what) {
        try {
            return Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw new ExperimentException(what + ": not a whole number: '" + text + "'");
        }
    }
}
