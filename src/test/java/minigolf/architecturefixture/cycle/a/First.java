package minigolf.architecturefixture.cycle.a;

import minigolf.architecturefixture.cycle.b.Second;

/** Half of a deliberate package cycle: ArchitectureTest shows its cycle rule reports one. */
public final class First {
    public Second next() {
        return new Second();
    }
}
