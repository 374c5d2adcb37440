package minigolf.architecturefixture.cycle.b;

import minigolf.architecturefixture.cycle.a.First;

/** The other half of the deliberate package cycle (see {@link First}). */
public final class Second {
    public First back() {
        return new First();
    }
}
